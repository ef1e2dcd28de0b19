#pragma once
// Compiler-style diagnostics: `file:line:col: error: message`, the source line, a caret.
// One Diagnostics object per input file; nothing here is global, so a batch can post many files
// at once.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "support/source_loc.h"

namespace clpost {

enum class Severity { kNote, kWarning, kError };
// "note", "warning", "error".
std::string_view severity_name(Severity s);

struct Diagnostic {
  Severity severity = Severity::kError;
  SourceLoc loc;
  std::string message;
  // The physical source line for the caret display (may be empty). A line longer than
  // kMaxExcerpt keeps only a window of it around the column: line_text then starts at column
  // `first_col` of the line, and `cut_after` says whether the line goes on past the window.
  std::string line_text;
  uint32_t first_col = 1;
  bool cut_after = false;
};

class Diagnostics {
 public:
  explicit Diagnostics(std::string file_name) : file_(std::move(file_name)) {}

  // `line_text` is the physical line `loc.line` refers to (copied; may be empty).
  void error(SourceLoc loc, std::string_view line_text, std::string message);
  void warning(SourceLoc loc, std::string_view line_text, std::string message);
  void note(SourceLoc loc, std::string_view line_text, std::string message);
  void add(Severity severity, SourceLoc loc, std::string_view line_text, std::string message);

  const std::string& file() const { return file_; }
  size_t error_count() const { return errors_; }
  size_t warning_count() const { return warnings_; }
  bool has_errors() const { return errors_ > 0; }
  // Diagnostics kept for display. Only the first kMaxKept are stored (memory stays bounded on
  // hostile input); the counts above include all of them.
  const std::vector<Diagnostic>& kept() const { return kept_; }
  size_t dropped() const { return dropped_; }
  // When true, warnings are counted as errors (clpost --strict).
  void set_warnings_are_errors(bool on) { werror_ = on; }
  // Binary input (a CLDATA file): a location is SourceLoc{record, byte offset + 1}, rendered
  // `file: record 17 (byte 1040): error: ...`, and the line shown is the record's APT text,
  // without a caret.
  void set_binary_records(bool on) { binary_records_ = on; }
  bool binary_records() const { return binary_records_; }

  static constexpr size_t kMaxKept = 200;
  // The most characters of a source line kept for the caret display.
  static constexpr size_t kMaxExcerpt = 200;

  // `file:line:col: error: message` + source line + caret line (each ending in '\n').
  std::string render(const Diagnostic& d) const;
  // Every kept diagnostic, then a line about the ones not kept.
  std::string render_all() const;

 private:
  std::string file_;
  std::vector<Diagnostic> kept_;
  size_t errors_ = 0;
  size_t warnings_ = 0;
  size_t dropped_ = 0;
  bool werror_ = false;
  bool binary_records_ = false;
};

}  // namespace clpost
