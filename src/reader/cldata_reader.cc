#include "reader/cldata_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>

#include "reader/cldata_words.h"
#include "reader/continuation.h"
#include "support/text.h"

namespace clpost {

using namespace cldata;

namespace {

constexpr size_t kChunk = 64 * 1024;

bool is_name_char(char c) {
  return (c >= 'A' && c <= 'Z') || is_digit(c);
}

std::string_view trim_blanks(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

// `v` as text that reads back as exactly `v`. CL coordinates have few decimals: when n / 10^6
// (correctly rounded, as a reader rounds the decimal text) is v, v is written as n with six
// decimals, its trailing zeros dropped (n / 10^k is then the same number). Anything else is
// written as its shortest round trip by fmt.
void append_number(std::string& out, double v) {
  if (std::fabs(v) < 1e9 && !(v == 0 && std::signbit(v))) {
    const double scaled = v * 1e6;  // |scaled| < 1e15: exact in an int64_t and a double
    int64_t n = static_cast<int64_t>(scaled + (v < 0 ? -0.5 : 0.5));
    if (static_cast<double>(n) / 1e6 == v) {
      int k = 6;
      while (k > 0 && n % 10 == 0) n /= 10, --k;
      char digits[24];
      const auto r = std::to_chars(digits, digits + sizeof digits, n < 0 ? -n : n);
      const std::string_view d(digits, static_cast<size_t>(r.ptr - digits));
      const size_t decimals = static_cast<size_t>(k);
      if (v < 0) out += '-';
      if (decimals == 0) return void(out += d);
      if (d.size() <= decimals) {
        out.append("0.").append(decimals - d.size(), '0').append(d);
      } else {
        out.append(d.substr(0, d.size() - decimals))
            .append(".")
            .append(d.substr(d.size() - decimals));
      }
      return;
    }
  }
  fmt::format_to(std::back_inserter(out), "{}", v);
}

}  // namespace

// A word as a number, a minor word code, a name (text), or blanks.
struct CldataReader::Word {
  enum class Kind { kNumber, kCode, kText, kBlank } kind;
  double number = 0;
  int64_t code = 0;
  std::string_view text;  // kText: trimmed, in the input buffer
};

CldataReader::CldataReader(const Layout& layout, std::string_view head, std::FILE* in,
                           Diagnostics& diags)
    : layout_(layout), diags_(diags), in_(in) {
  take_raw(head);
  eof_ = in == nullptr;
  diags_.set_binary_records(true);
}

CldataReader::CldataReader(const Layout& layout, std::string_view data, Diagnostics& diags)
    : layout_(layout), diags_(diags), data_(data.data()), len_(data.size()), eof_(true) {
  if (layout_.block_words != 0) {
    data_ = nullptr, len_ = 0;
    take_raw(data);  // blocks joined into storage_
  }
  diags_.set_binary_records(true);
}

// The file's next bytes, `raw`, appended to the unread input (blocked layouts: joined).
void CldataReader::take_raw(std::string_view raw) {
  append_records(layout_, storage_, raw, raw_read_);
  raw_read_ += raw.size();
  data_ = storage_.data();
  len_ = storage_.size();
}

// Makes n unread bytes available; false at the end of the input (or a read error, reported).
bool CldataReader::ensure(size_t n) {
  while (len_ - pos_ < n && !eof_) {
    storage_.erase(0, pos_);
    base_ += pos_;
    pos_ = 0;
    const size_t want = std::max(kChunk, n - storage_.size());
    raw_.resize(want);
    const size_t got = std::fread(raw_.data(), 1, want, in_);
    take_raw(std::string_view(raw_).substr(0, got));
    if (got < want) {
      eof_ = true;
      if (std::ferror(in_)) {
        error(SourceLoc{}, fmt::format("error reading input: {}", std::strerror(errno)));
        stop();
        return false;
      }
    }
  }
  return len_ - pos_ >= n;
}

void CldataReader::error(SourceLoc loc, std::string message) {
  diags_.error(loc, {}, std::move(message));
  if (++errors_ >= kMaxErrors && !done_) {
    diags_.note(SourceLoc{}, {}, "too many errors, stopping");
    stop();
  }
}

void CldataReader::stop() {
  done_ = true;
  gave_up_ = true;
}

// Reads the next record's header and words into the buffer; false at the end or when the
// input cannot be read on (reported).
bool CldataReader::read_record() {
  const size_t hb = layout_.header_bytes();
  if (!ensure(hb)) {
    if (len_ > pos_) {
      error(SourceLoc{ordinal_ + 1, loc_at(logical_read()).col},
            fmt::format("truncated record: {} bytes where a {}-byte header should be", len_ - pos_,
                        hb));
      stop();
    }
    done_ = true;
    return false;
  }
  ++ordinal_;
  record_at_ = logical_read();
  header_ = read_header(layout_, data_ + pos_);
  const SourceLoc at = loc_at(record_at_);
  if (header_.length < 0 || header_.length > kMaxRecordWords) {
    error(at, fmt::format("impossible record length {} words (type {}); reading stops here",
                          header_.length, header_.type));
    stop();
    return false;
  }
  count_ = static_cast<size_t>(header_.length);
  const size_t body = count_ * layout_.word_bytes;
  if (!ensure(hb + body)) {
    if (done_) return false;  // a read error
    error(at, fmt::format("truncated record: type {} of {} words ({} bytes), {} bytes left",
                          header_.type, count_, body, len_ - pos_ - hb));
    stop();
    return false;
  }
  words_ = data_ + pos_ + hb;
  pos_ += hb + body;
  next_word_ = 0;
  in_record_ = true;
  return true;
}

CldataReader::Word CldataReader::word(size_t i) const {
  const char* p = words_ + i * layout_.word_bytes;
  const uint64_t bits = read_word(layout_, p);
  if (const std::optional<int64_t> code = word_code(layout_, bits))
    return Word{Word::Kind::kCode, 0, *code, {}};
  const std::string_view chars(p, layout_.word_bytes);
  const std::string_view text = chars.substr(0, layout_.text_chars);
  bool name = true, blank = true;
  for (char c : text) name = name && (c == ' ' || is_name_char(c)), blank = blank && c == ' ';
  for (char c : chars.substr(layout_.text_chars)) name = name && c == ' ';
  if (name && blank) return Word{Word::Kind::kBlank, 0, 0, {}};
  // A name starts with a letter (digits alone would be a number in the APT text) and has no
  // blank inside (it would be two words).
  const std::string_view trimmed = trim_blanks(text);
  if (name && trimmed.front() >= 'A' && trimmed.front() <= 'Z' &&
      trimmed.find(' ') == std::string_view::npos)
    return Word{Word::Kind::kText, 0, 0, trimmed};
  return Word{Word::Kind::kNumber, word_double(bits), 0, {}};
}

// Record and byte: SourceLoc{record, byte + 1} (column 0, no byte, past 4 GB). `logical`, a byte
// of the record stream, is shown as its offset in the file.
SourceLoc CldataReader::loc_at(size_t logical) const {
  const size_t byte = file_offset(layout_, logical);
  return SourceLoc{ordinal_, byte + 1 > UINT32_MAX ? 0 : static_cast<uint32_t>(byte + 1)};
}

SourceLoc CldataReader::loc_of_word(size_t i) const {
  return loc_at(record_at_ + layout_.header_bytes() + i * layout_.word_bytes);
}

bool CldataReader::next(Statement& out) {
  while (!done_) {
    if (!in_record_ && !read_record()) break;
    if (statement_of_record(out)) return true;
  }
  return false;
}

// The next statement of the current record; false when it has no more (in_record_ cleared).
bool CldataReader::statement_of_record(Statement& out) {
  const SourceLoc at = loc_at(record_at_);
  if (layout_.flavor == Flavor::kNcl)
    if (const std::optional<bool> r = ncl_record(out)) return *r;
  switch (header_.type) {
    case kPostWord:
      in_record_ = false;
      return post_word(out);
    case kMotion:
      return motion(out);
    case kTool:
    case kMultiAxis: {
      in_record_ = false;
      const std::string_view major =
          subtype_name(static_cast<int32_t>(header_.type), header_.subtype);
      if (major.empty()) break;
      begin(out, major, count_ ? Statement::Form::kRecord : Statement::Form::kBare, at);
      for (size_t i = 0; i < count_; ++i)
        if (!add_word_arg(out, i)) return false;
      finish(out);
      if (major == "MULTAX" && !out.args.empty()) multax_ = out.args[0].is("ON");
      return true;
    }
    case kFini:
      in_record_ = false;
      begin(out, "FINI", Statement::Form::kBare, at);
      finish(out);
      after_fini();
      return true;
    default:
      break;
  }
  in_record_ = false;
  if (header_.type == kSequence || header_.type == kSurface) {
    comment_of_record();
    return false;
  }
  diags_.warning(at, {},
                 fmt::format("unknown {} {} (subtype {}, {} words); skipped",
                             is_known_type(header_.type, layout_.flavor == Flavor::kNcl)
                                 ? "subtype of record type"
                                 : "record type",
                             header_.type, header_.subtype, count_));
  comment_of_record();
  return false;
}

bool CldataReader::post_word(Statement& out) {
  const SourceLoc at = loc_at(record_at_);
  const bool ncl = layout_.flavor == Flavor::kNcl;
  std::string_view major = ncl ? ncl_major_name(header_.subtype) : major_name(header_.subtype);
  std::string code;
  if (major.empty()) major = code = fmt::format("CODE{}", header_.subtype);
  if (ncl ? ncl_is_text_major(header_.subtype) : is_text_major(header_.subtype)) {
    std::string& text = comment_text_;
    text.clear();
    for (size_t i = 0; i < count_; ++i)
      text.append(words_ + i * layout_.word_bytes, layout_.text_chars);
    return text_statement(out, major, text);
  }
  begin(out, major, count_ ? Statement::Form::kRecord : Statement::Form::kBare, at);
  for (size_t i = 0; i < count_; ++i)
    if (!add_word_arg(out, i)) return false;
  finish(out);
  return true;
}

// A text statement (PARTNO, PPRINT, INSERT; NCL's REMARK) of `text`, the record's characters.
bool CldataReader::text_statement(Statement& out, std::string_view major, std::string& text) {
  const SourceLoc at = loc_at(record_at_);
  bool odd = false;
  for (char& ch : text) {
    const bool printable = ch >= 0x20 && ch < 0x7f;
    odd = odd || !printable;
    if (!printable) ch = '?';
  }
  if (odd)
    diags_.warning(at, {},
                   fmt::format("{} text holds bytes that are not text, read as '?'", major));
  // A text ending in one '$' would continue onto the next line when read as APT: its APT text
  // (cl2apt) could not say it, so the '$' is read as '?', like a byte that is not text.
  const std::string_view end = trim_blanks(text);
  if (reader::comment_continues(end)) {
    text[static_cast<size_t>(end.data() - text.data()) + end.size() - 1] = '?';
    diags_.warning(at, {},
                   fmt::format("{} text ends in '$', which APT reads as a continuation: read as "
                               "'?'",
                               major));
  }
  begin(out, major, Statement::Form::kText, at);
  const std::string_view trimmed = trim_blanks(text);
  // A text that starts with '/' keeps it: the text reader takes one '/' after the major.
  if (!trimmed.empty()) line_.append(trimmed.front() == '/' ? " /" : " ").append(trimmed);
  finish(out);
  out.text = std::string_view(line_).substr(line_.size() - trimmed.size());
  return true;
}

// One statement per point of a FROM, GOTO or continuation record; one statement of all its
// numbers for the other kinds (GODLTA, INDIRV, ...).
bool CldataReader::motion(Statement& out) {
  if (next_word_ == 0)  // APT360: after the surface name pair
    next_word_ = std::min<size_t>(layout_.motion_name_words, count_);
  const int64_t sub = header_.subtype;
  std::string_view major = sub == kMotionContinuation ? motion_major_ : subtype_name(kMotion, sub);
  if (major.empty()) {
    in_record_ = false;
    diags_.warning(loc_at(record_at_), {},
                   fmt::format("unknown subtype of record type 5000 (subtype {}, {} words); "
                               "skipped",
                               sub, count_));
    comment_of_record();
    return false;
  }
  if (sub == 3 || sub == 5) motion_major_ = major;
  const bool points = sub == 3 || sub == 5 || sub == kMotionContinuation;
  const size_t n = points ? (multax_ ? 6 : 3) : count_ - next_word_;
  if (next_word_ >= count_ || n == 0) {
    if (count_ <= 2) comment_of_record();  // no points at all: still a line for cl2apt
    in_record_ = false;
    return false;
  }
  if (next_word_ + n > count_) {
    error(loc_of_word(next_word_),
          fmt::format("{} record ends in the middle of a point: {} of {} coordinates", major,
                      count_ - next_word_, n));
    in_record_ = false;
    return false;
  }
  const size_t from = next_word_;
  next_word_ += n;
  return numbered(out, major, from);
}

// `major` with the numbers of words [from, next_word_).
bool CldataReader::numbered(Statement& out, std::string_view major, size_t from) {
  begin(out, major, Statement::Form::kRecord, loc_of_word(from));
  for (size_t i = from; i < next_word_; ++i) {
    // A coordinate is a double, whatever its bytes look like, unless it is a word code.
    const uint64_t bits = read_word(layout_, words_ + i * layout_.word_bytes);
    if (word_code(layout_, bits)) {
      error(loc_of_word(i), fmt::format("{} coordinate {} is not a number", major, i - from + 1));
      return false;
    }
    const double v = word_double(bits);
    if (!std::isfinite(v)) {
      error(loc_of_word(i),
            fmt::format("{} coordinate {} is not a finite number", major, i - from + 1));
      return false;
    }
    add_number(out, v, loc_of_word(i));
  }
  finish(out);
  return true;
}

// Adds word i as an argument: a number, a minor word, or a name. False (reported) for a number
// that is not finite.
bool CldataReader::add_word_arg(Statement& out, size_t i) {
  const Word w = word(i);
  switch (w.kind) {
    case Word::Kind::kBlank:
      return true;
    case Word::Kind::kText:
      add_word(out, w.text, loc_of_word(i));
      return true;
    case Word::Kind::kCode: {
      const std::string_view name =
          layout_.flavor == Flavor::kNcl ? ncl_minor_name(w.code) : minor_name(w.code);
      if (!name.empty()) {
        add_word(out, name, loc_of_word(i));
      } else {
        add_word(out, fmt::format("CODE{}", w.code), loc_of_word(i));
      }
      return true;
    }
    case Word::Kind::kNumber:
      if (!std::isfinite(w.number)) {
        error(loc_of_word(i), fmt::format("{} word {} is not a finite number",
                                          std::string_view(line_).substr(0, major_size_), i + 1));
        return false;
      }
      add_number(out, w.number, loc_of_word(i));
      return true;
  }
  return true;
}

void CldataReader::begin(Statement& out, std::string_view major, Statement::Form form,
                         SourceLoc loc) {
  line_.assign(major);
  major_size_ = major.size();
  pending_.clear();
  out.form = form;
  out.loc = loc;
  out.text = {};
  out.args.clear();
  // What the text reader fills that binary records never have.
  out.modifiers.clear();
  out.nested.clear();
  out.problem = LexProblem{};
}

void CldataReader::add_number(Statement& out, double v, SourceLoc loc) {
  line_ += pending_.empty() ? '/' : ',';
  const size_t at = line_.size();
  append_number(line_, v);
  pending_.push_back(Pending{Arg::Kind::kNumber, at, line_.size() - at, v, loc});
  (void)out;
}

void CldataReader::add_word(Statement& out, std::string_view w, SourceLoc loc) {
  line_ += pending_.empty() ? '/' : ',';
  pending_.push_back(Pending{Arg::Kind::kWord, line_.size(), w.size(), 0, loc});
  line_ += w;
  (void)out;
}

// The statement's views, into line_ (which does not change until the next statement).
void CldataReader::finish(Statement& out) {
  // A record whose words were all blank: the major alone, as the text reader reads it.
  if (out.form == Statement::Form::kRecord && pending_.empty()) out.form = Statement::Form::kBare;
  const std::string_view line(line_);
  out.major = line.substr(0, major_size_);
  for (const Pending& p : pending_) {
    Arg& a = out.args.emplace_back();
    a.kind = p.kind;
    a.text = line.substr(p.offset, p.size);
    a.number = p.number;
    a.loc = p.loc;
  }
  out.first_line = ordinal_;
  out.lines.assign(1, line);
  out.source = line;  // the statement as written: its APT text
}

void CldataReader::comment_of_record() {
  if (!comment_) return;
  std::string& c = comment_text_;
  c.clear();
  if (header_.type == kSequence) {
    c = fmt::format("ISN {}", header_.subtype);
  } else if (header_.type == kSurface && count_ >= 5 && word(1).kind == Word::Kind::kCode &&
             !surface_name(word(1).code).empty()) {
    // APT360: 0, surface type, words that follow, name, subscript, canonical form.
    const Word name = word(3);
    c = fmt::format("surface {}: {}/", name.kind == Word::Kind::kText ? name.text : "?",
                    surface_name(word(1).code));
    for (size_t i = 5; i < count_; ++i) {
      const Word w = word(i);
      if (i > 5) c += ',';
      if (w.kind == Word::Kind::kNumber)
        fmt::format_to(std::back_inserter(c), "{}", w.number);
      else
        c += '?';
    }
  } else {
    c = fmt::format("record {} skipped: type {}, subtype {}, {} words", ordinal_, header_.type,
                    header_.subtype, count_);
  }
  comment_(c);
}

// FINI ends the file: what follows (tape padding) is not read as records. A blocked layout's
// last block is filled up after FINI: that is not noted.
void CldataReader::after_fini() {
  const size_t fini_end = logical_read();
  size_t rest = 0;
  for (;;) {
    rest += len_ - pos_;
    pos_ = len_;
    if (eof_ || !ensure(1)) break;
  }
  if (layout_.block_words != 0) {
    const size_t data = layout_.block_data_bytes();
    rest -= std::min(rest, (data - fini_end % data) % data);
  }
  if (rest > 0 && !gave_up_)
    diags_.note(loc_at(record_at_), {}, fmt::format("{} bytes after FINI ignored", rest));
  done_ = true;
}

}  // namespace clpost
