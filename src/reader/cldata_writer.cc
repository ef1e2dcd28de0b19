#include "reader/cldata_writer.h"

#include <fmt/format.h>

#include <bit>
#include <vector>

#include "reader/cl_reader.h"
#include "reader/cldata_words.h"
#include "support/text.h"

namespace clpost::cldata {

void Writer::put(uint64_t v, size_t bytes) {
  for (size_t i = 0; i < bytes; ++i) {
    const size_t shift = 8 * (layout_.little_endian ? i : bytes - 1 - i);
    out_ += static_cast<char>((v >> shift) & 0xff);
  }
}

// Blocked layouts: the unused last word of a physical block before the next word.
void Writer::skip_unused() {
  if (layout_.block_words == 0) return;
  const size_t word = out_.size() / layout_.word_bytes;
  if (word % layout_.block_words == layout_.block_words - 1u) out_.append(layout_.word_bytes, '\0');
}

void Writer::record(int64_t type, int64_t subtype, std::span<const uint64_t> words) {
  int64_t f[8] = {};
  ++number_;
  if (layout_.number_at >= 0) f[layout_.number_at] = number_;
  if (layout_.isn_at >= 0) f[layout_.isn_at] = number_;
  f[layout_.length_at] =
      static_cast<int64_t>(words.size()) + (layout_.length_counts_header ? 1 : 0);
  f[layout_.type_at] = type;
  f[layout_.subtype_at] = subtype;
  skip_unused();  // a blocked layout's header is one word
  for (size_t i = 0; i < layout_.fields; ++i) put(static_cast<uint64_t>(f[i]), layout_.field_bytes);
  for (uint64_t w : words) {
    skip_unused();
    put(w, layout_.word_bytes);
  }
  // NCL fills the last block up after FINI.
  if (type == kFini && layout_.block_words != 0 && out_.size() % layout_.block_bytes() != 0)
    out_.append(layout_.block_bytes() - out_.size() % layout_.block_bytes(), '\0');
}

uint64_t Writer::number(double v) {
  return std::bit_cast<uint64_t>(v);
}

uint64_t Writer::text(std::string_view chars) const {
  std::string w(chars.substr(0, layout_.text_chars));
  w.resize(layout_.word_bytes, ' ');
  uint64_t v = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    const size_t shift = 8 * (layout_.little_endian ? i : w.size() - 1 - i);
    v |= static_cast<uint64_t>(static_cast<unsigned char>(w[i])) << shift;
  }
  return v;
}

namespace {

class Encoder {
 public:
  Encoder(Diagnostics& diags, const EncodeOptions& opts) : diags_(diags), opts_(opts) {}
  void statement(const Statement& st);
  void record_of(const Statement& st);
  void flush();
  const std::string& bytes() const { return w_.bytes(); }

 private:
  bool args(const Statement& st, std::vector<uint64_t>& words);
  bool text_statement(const Statement& st, int64_t code);
  void fail(const Statement& st, std::string message) {
    diags_.error(st.loc, st.line_text(st.loc.line), std::move(message));
  }

  Diagnostics& diags_;
  const EncodeOptions& opts_;
  Writer w_;
  std::vector<uint64_t> points_;  // GOTO coordinates not yet written
  bool continuing_ = false;       // the next GOTO record continues the last one
  bool multax_ = false;
  uint32_t line_ = 0;  // line_aligned: the last line that has its record
  void sequence(uint32_t line) {
    w_.record(kSequence, line, std::vector<uint64_t>{0, w_.text("")});
  }
  // line_aligned: a statement's continuation lines have sequence records after its own.
  void continuations(const Statement& st) {
    if (!opts_.line_aligned) return;
    for (uint32_t l = 1; l < st.lines.size(); ++l) sequence(st.first_line + l);
  }
};

// A statement's arguments as words: numbers, minor word codes, short names as text.
bool Encoder::args(const Statement& st, std::vector<uint64_t>& words) {
  for (const Arg& a : st.args) {
    if (a.is_number()) {
      words.push_back(Writer::number(a.number));
      continue;
    }
    const int64_t code = minor_code(a.text);
    bool name = a.text.size() <= 6 && !a.text.empty();
    for (char c : a.text) name = name && ((c >= 'A' && c <= 'Z') || is_digit(c));
    if (code < 0 && !name) {
      fail(st, fmt::format("the word '{}' has no CLDATA code and is not a name", a.text));
      return false;
    }
    words.push_back(code >= 0 ? Writer::code(code) : w_.text(a.text));
  }
  return true;
}

bool Encoder::text_statement(const Statement& st, int64_t code) {
  std::vector<uint64_t> words;
  for (size_t i = 0; i < st.text.size(); i += 6) words.push_back(w_.text(st.text.substr(i, 6)));
  w_.record(kPostWord, code, words);
  return true;
}

void Encoder::flush() {
  if (points_.empty()) return;
  std::vector<uint64_t> words{0, 0};
  words.insert(words.end(), points_.begin(), points_.end());
  w_.record(kMotion, continuing_ ? kMotionContinuation : 5, words);
  continuing_ = true;
  points_.clear();
}

void Encoder::statement(const Statement& st) {
  record_of(st);
  continuations(st);
}

void Encoder::record_of(const Statement& st) {
  const std::string_view m = st.major;
  const bool point = m == "GOTO" && st.args.size() == (multax_ ? 6u : 3u);
  if (!point) {
    flush();
    continuing_ = false;
  }
  if (opts_.line_aligned) {
    while (line_ + 1 < st.first_line) sequence(++line_);
    line_ = st.first_line + static_cast<uint32_t>(st.lines.size()) - 1;
  } else if (points_.empty()) {
    sequence(st.first_line);
  }
  std::vector<uint64_t> words;
  if (point) {
    if (args(st, words)) points_.insert(points_.end(), words.begin(), words.end());
    if (opts_.line_aligned || points_.size() >= opts_.points_per_record * st.args.size()) flush();
    return;
  }
  if (st.form == Statement::Form::kText) {
    const int64_t code = major_code(m);
    if (code >= 0)
      text_statement(st, code);
    else
      fail(st, fmt::format("{} has no CLDATA record", m));
    return;
  }
  if (m == "FINI") return w_.record(kFini, 0, {});
  int64_t type = kPostWord, sub = -1;
  if (m == "FROM" || m == "GODLTA") {
    type = kMotion, sub = subtype_code(kMotion, m);
    words = {0, 0};
  } else if ((sub = subtype_code(kTool, m)) >= 0) {
    type = kTool;
  } else if ((sub = subtype_code(kMultiAxis, m)) >= 0) {
    type = kMultiAxis;
    if (m == "MULTAX") multax_ = !st.args.empty() && st.args[0].is("ON");
  } else {
    sub = major_code(m);
  }
  if (sub < 0) return fail(st, fmt::format("{} has no CLDATA record", m));
  if (args(st, words)) w_.record(type, sub, words);
}

}  // namespace

bool encode_apt(std::string_view apt, Diagnostics& diags, std::string& out,
                const EncodeOptions& opts) {
  ClReader reader(apt, diags);
  Encoder enc(diags, opts);
  Statement st;
  while (reader.next(st)) enc.statement(st);
  enc.flush();
  out = enc.bytes();
  return !diags.has_errors();
}

}  // namespace clpost::cldata
