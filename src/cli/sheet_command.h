#pragma once
// `clpost sheet` and `--sheet DIR` / `--sheets`: the setup sheet of a posted file (sheet/sheet.h),
// built from the PostOutcome of the very post that wrote (or would write) the program, so its
// tools, times, threads and holes are the values `clpost check` and `clpost plan` print.
#include <string>
#include <vector>

#include "cli/post_file.h"
#include "machine/machine.h"

namespace clpost {

enum class SheetFormat { kHtml, kJson };

// What a sheet says about where it comes from.
struct SheetInfo {
  std::string nc_file;  // the program it goes with ("": not written)
  std::string date;     // sheet_date()
  SheetFormat format = SheetFormat::kHtml;
};

// What a post leaves for its sheet: hand `plans` and `program` to the PostRequest
// (on_thread, program) with sheet_request().
struct SheetCapture {
  std::vector<ThreadPlan> plans;
  std::string program;
};
void sheet_request(PostRequest& req, SheetCapture& capture);

// The sheet of the posted file `input` (outcome `r`, which must be ok) as text; false, with
// the diagnostics, when the program cannot be run through the control simulation.
bool sheet_text(const std::string& input, const PostOutcome& r, SheetCapture& capture,
                const Machine& m, const SheetInfo& info, std::string& text,
                std::string& diagnostics);

// Writes `text` to `path` atomically ("-": standard output); false with a message.
bool write_text_file(const std::string& path, const std::string& text, std::string& diagnostics);

// DIR/<stem of `input`>.html (.json): where --sheet DIR puts a file's sheet.
std::string sheet_path_in(const std::string& dir, const std::string& input, SheetFormat f);

// `clpost sheet`: post `input` on `m` (nothing written but the sheet) and write its sheet to
// `output` ("-": standard output). 0 ok, 1 input errors.
struct SheetRequest {
  std::string input;
  std::string output = "-";
  SheetInfo info;
  const Machine* machine = nullptr;
};
struct SheetOutcome {
  bool ok = false;
  std::string diagnostics;
};
SheetOutcome sheet_file(const SheetRequest& req);

}  // namespace clpost
