#include "writer/nc_writer.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>

#include "writer/number_format.h"

namespace clpost {

namespace {

// The one-character texts of every block (a block address, a line ending): a memcpy call costs
// more than the copy.
void append_short(BlockBuffer& b, std::string_view s) {
  if (s.size() == 1) return b.push_back(s[0]);
  b.append(s);
}

}  // namespace

NcWriter::NcWriter(const Machine& m, Sink& out)
    : m_(m),
      out_(out),
      plain_blocks_(!m.numbers_at_tool_changes),
      line_limit_(m.max_line_length > 0 ? static_cast<size_t>(m.max_line_length) : SIZE_MAX),
      next_number_(m.block_start) {}

void NcWriter::set_block_delete(std::string_view mark) {
  block_delete_ = mark;
  plain_blocks_ = block_delete_.empty() && !m_.numbers_at_tool_changes;
}

// Every block comes here (every GOTO is one): a block without block delete whose number only
// depends on block_numbers.enabled takes one test before its number.
void NcWriter::open_block() {
  open_ = true;
  line_.clear();
  if (plain_blocks_) {
    numbered_ = m_.block_numbers;
  } else {
    line_.append(block_delete_);
    numbered_ = m_.block_numbers && (!m_.numbers_at_tool_changes || number_next_);
    number_next_ = false;
  }
  if (numbered_) {
    // "N120 ": the address, the number, a blank.
    append_short(line_, m_.block_address);
    char* p = line_.room(16);
    p = std::to_chars(p, p + 15, next_number_).ptr;
    *p++ = ' ';
    line_.commit(p);
  }
  words_at_ = line_.size();
}

NcWriter& NcWriter::code(std::string_view c) {
  if (c.empty()) return *this;
  separate();
  line_.append(c);
  return *this;
}

NcWriter& NcWriter::word(std::string_view address, double value) {
  return word(address, value, m_.format_for(address));
}

NcWriter& NcWriter::text(std::string_view raw) {
  return code(raw);
}

void NcWriter::end_block() {
  if (!open_) return;
  if (numbered_) {
    bool unnumbered = false;
    const std::string_view w = words();
    for (const std::string& prefix : m_.block_skip)
      if (!prefix.empty() && w[0] == prefix[0] && w.starts_with(prefix)) unnumbered = true;
    if (unnumbered) {
      line_.erase_front(words_at_);
    } else {
      next_number_ += m_.block_step;
      if (next_number_ > m_.block_max) next_number_ = m_.block_start;
    }
  }
  ++lines_;
  if (line_.size() > line_limit_ && long_lines_++ == 0) first_long_line_ = lines_;
  append_short(line_, m_.line_ending);
  out_.write(line_.view());
  open_ = false;
}

std::string NcWriter::comment_text(const Machine& m, std::string_view text) {
  std::string clean;
  clean.reserve(text.size());
  const std::string_view control = m.control ? m.control->comment_control : std::string_view();
  // A comment that closes cannot hold its own delimiters: "(A (B))" ends at the first ')'.
  const std::string_view delimiters =
      m.comment_close.empty() ? std::string_view() : std::string_view(m.comment_open);
  for (char c : text) {
    if (m.comment_forbidden.find(c) != std::string::npos) continue;
    if (control.find(c) != std::string_view::npos) continue;
    if (delimiters.find(c) != std::string_view::npos) continue;
    if (m.comment_close.find(c) != std::string::npos) continue;
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
    clean += m.comment_upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
  }
  // Trim: a comment should read as the CL wrote it, without padding.
  size_t b = clean.find_first_not_of(' ');
  size_t e = clean.find_last_not_of(' ');
  return b == std::string::npos ? std::string() : clean.substr(b, e - b + 1);
}

std::vector<std::string> NcWriter::comment_lines(const Machine& m, std::string_view text) {
  std::string clean = comment_text(m, text);
  const size_t max = static_cast<size_t>(m.comment_max_length);
  std::vector<std::string> lines;
  while (max > 0 && clean.size() > max) {
    size_t cut = clean.rfind(' ', max);
    if (cut == std::string::npos || cut == 0) cut = max;
    lines.push_back(clean.substr(0, cut));
    const size_t next = clean.find_first_not_of(' ', cut);
    clean = next == std::string::npos ? std::string() : clean.substr(next);
  }
  lines.push_back(std::move(clean));
  return lines;
}

void NcWriter::comment(std::string_view text) {
  const std::vector<std::string> lines = comment_lines(m_, text);
  if (lines.size() > 1) ++wrapped_comments_;
  for (const std::string& l : lines) {
    code(m_.comment_open + l + m_.comment_close);
    end_block();
  }
}

void NcWriter::raw_line(std::string_view text) {
  ++lines_;
  out_.write(text);
  out_.write(m_.line_ending);
}

}  // namespace clpost
