#pragma once
// Reader of binary CLDATA files (ISO 3592 records: 2000 post words, 5000 motion, ...), in APT360's
// layouts and NCL's (its physical blocks joined, its own records read: cldata_ncl.cc). It yields
// the statements the text reader yields for the equivalent APT source — the same major words,
// minor words, numbers and text — so everything after the reader works on either. A record
// of many points gives one GOTO per point. Sequence numbers (1000) and surface data (3000) make
// no statement. Locations are record numbers and byte offsets: SourceLoc{record, byte + 1},
// rendered by Diagnostics as `file: record 17 (byte 1040)`; each statement's "line" is its APT
// text. ClReader hands binary input to this reader by itself (cl_reader.h).
#include <cstddef>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "reader/cldata_layout.h"
#include "reader/statement.h"
#include "support/diagnostics.h"

namespace clpost {

class CldataReader {
 public:
  // `head`: the first bytes of the input, already read from `in` (copied); then the rest of
  // `in` (not owned; may be null).
  CldataReader(const cldata::Layout& layout, std::string_view head, std::FILE* in,
               Diagnostics& diags);
  // The whole input in memory; `data` must outlive the reader.
  CldataReader(const cldata::Layout& layout, std::string_view data, Diagnostics& diags);
  CldataReader(const CldataReader&) = delete;
  CldataReader& operator=(const CldataReader&) = delete;

  // As ClReader::next().
  bool next(Statement& out);

  // Bytes of the file read (NCL: the blocks' unused words counted).
  size_t bytes_read() const {
    const size_t at = cldata::file_offset(layout_, logical_read());
    return layout_.block_words != 0 && at > raw_read_ ? raw_read_ : at;
  }
  uint32_t record() const { return ordinal_; }
  bool gave_up() const { return gave_up_; }
  const cldata::Layout& layout() const { return layout_; }
  // Records that make no statement (sequence numbers, surface data, records skipped) are
  // handed to `f` as the text of an APT comment, for cl2apt.
  void on_comment(std::function<void(std::string_view)> f) { comment_ = std::move(f); }

  static constexpr size_t kMaxErrors = 100;
  // A record longer than this is a damaged length (APT360 writes at most 242 words). Its APT
  // text stays well under ClReader::kMaxStatementBytes.
  static constexpr int64_t kMaxRecordWords = 1 << 14;

 private:
  struct Word;
  size_t logical_read() const { return base_ + pos_; }
  void take_raw(std::string_view raw);
  bool read_record();
  bool ensure(size_t n);
  bool statement_of_record(Statement& out);
  bool post_word(Statement& out);
  bool text_statement(Statement& out, std::string_view major, std::string& text);
  // NCL's own records (cldata_ncl.cc): true or false as statement_of_record() returns, nothing
  // for a record read as APT360's.
  std::optional<bool> ncl_record(Statement& out);
  bool ncl_header(Statement& out);
  bool ncl_multax(Statement& out);
  bool ncl_cutter(Statement& out);
  bool motion(Statement& out);
  bool numbered(Statement& out, std::string_view major, size_t from);
  void comment_of_record();
  Word word(size_t i) const;
  SourceLoc loc_at(size_t byte) const;
  SourceLoc loc_of_word(size_t i) const;
  void begin(Statement& out, std::string_view major, Statement::Form form, SourceLoc loc);
  bool add_word_arg(Statement& out, size_t i);
  void add_number(Statement& out, double v, SourceLoc loc);
  void add_word(Statement& out, std::string_view w, SourceLoc loc);
  void finish(Statement& out);
  void error(SourceLoc loc, std::string message);
  void stop();
  void after_fini();

  const cldata::Layout& layout_;
  Diagnostics& diags_;
  std::function<void(std::string_view)> comment_;

  // Input: data_[0, len_) holds bytes from offset base_; pos_ is the next unread byte.
  std::FILE* in_ = nullptr;
  std::string storage_;  // file input (blocked layouts: also memory input), blocks joined
  std::string raw_;      // the bytes of the last read, before joining
  const char* data_ = nullptr;
  size_t len_ = 0;
  size_t pos_ = 0;
  size_t base_ = 0;
  bool eof_ = false;
  size_t raw_read_ = 0;  // bytes of the file read (blocked layouts: before joining)

  // The record being turned into statements.
  cldata::RecordHeader header_;
  size_t record_at_ = 0;         // its byte offset in the input
  const char* words_ = nullptr;  // its words (in data_)
  size_t count_ = 0;             // words
  size_t next_word_ = 0;         // motion: the next point's first word
  bool in_record_ = false;
  uint32_t ordinal_ = 0;                    // records read
  std::string_view motion_major_ = "GOTO";  // what a 5000/6 continuation continues
  bool multax_ = false;                     // points are x,y,z,i,j,k

  // The statement being built: its APT text (the diagnostics' line) and its arguments, as
  // offsets into it until finish() makes them views.
  std::string line_;
  struct Pending {
    Arg::Kind kind;
    size_t offset, size;
    double number;
    SourceLoc loc;
  };
  std::vector<Pending> pending_;
  size_t major_size_ = 0;
  bool major_in_line_ = false;
  std::string comment_text_;

  size_t errors_ = 0;
  bool done_ = false;
  bool gave_up_ = false;
};

}  // namespace clpost
