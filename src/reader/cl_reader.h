#pragma once
// Streaming reader for APT/CL source: one statement at a time, memory bounded by the longest
// statement (never by the file's length).
#include <cstddef>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "reader/statement.h"
#include "support/diagnostics.h"

namespace clpost {

class ClReader {
 public:
  // Reads from `in` (not owned, not closed) in large chunks.
  ClReader(std::FILE* in, Diagnostics& diags);
  // Reads from memory (tests, fuzzing). `text` must outlive the reader.
  ClReader(std::string_view text, Diagnostics& diags);
  ~ClReader();
  ClReader(const ClReader&) = delete;
  ClReader& operator=(const ClReader&) = delete;

  // Fills `out` with the next statement and returns true; returns false at the end of the input
  // (or when reading cannot go on: a read error, binary input, too many errors — reported in the
  // diagnostics). Lexical errors are reported and the bad statement is skipped.
  bool next(Statement& out);

  // Bytes consumed so far (progress, statistics).
  size_t bytes_read() const;
  // Number of the last physical line read.
  uint32_t line() const;
  // Reading stopped before the end of the input (binary data, a read error, too many errors):
  // the rest of the file was not read, so nothing should be said about how it ends.
  bool gave_up() const;

  // Limits on hostile input.
  static constexpr size_t kMaxStatementBytes = 1 << 20;  // a logical statement, continuations in
  static constexpr size_t kMaxErrors = 100;              // then stop reading

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clpost
