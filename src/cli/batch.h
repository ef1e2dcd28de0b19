#pragma once
// Batch posting: `clpost -m MACHINE -d OUTDIR INPUT…` posts every input (files, or the CL files
// in directories with -r) to OUTDIR/<stem><machine extension> on N worker threads. Every file is
// posted by post_file() (atomic output: a failed file leaves nothing and never replaces a good
// program). Results are reported in input order, so what the batch prints and writes does not
// depend on the number of workers (only the timings do).
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "cli/post_file.h"
#include "machine/machine.h"

namespace clpost {

// One input file and the program it becomes.
struct BatchItem {
  std::string input;
  std::string output;
};

// Expands the command line's inputs: files as given; directories (only with `recursive`) to the
// CL files under them (extensions in is_cl_file_name(), any case), sorted by path. False with a
// one-line message in `error` (a directory without -r, a directory with no CL file, an input
// that does not exist).
bool collect_inputs(const std::vector<std::string>& args, bool recursive,
                    std::vector<std::string>& files, std::string& error);

// .cl .cls .apt .ncl .aptsource .clsf .cldata (any case): what a directory walk picks up.
bool is_cl_file_name(const std::string& name);

// OUTDIR/<stem><extension> for every file. False when two inputs would write the same program
// (`error` names both), so that nothing is overwritten silently.
bool plan_outputs(const std::vector<std::string>& files, const std::string& out_dir,
                  const std::string& extension, std::vector<BatchItem>& items, std::string& error);

enum class FileStatus { kOk, kWarnings, kError, kNotPosted };

struct FileResult {
  BatchItem item;
  std::string sheet;  // the setup sheet written next to the program (--sheets), else ""
  FileStatus status = FileStatus::kNotPosted;
  PostOutcome outcome;  // empty when not posted
  double seconds = 0;
};

struct BatchSummary {
  size_t files = 0;
  size_t ok = 0;
  size_t with_warnings = 0;
  size_t failed = 0;
  size_t not_posted = 0;  // after a failure without --keep-going
  size_t errors = 0;      // diagnostics, all files
  size_t warnings = 0;
  size_t bytes_in = 0;
  size_t bytes_out = 0;
  double seconds = 0;  // wall clock, the whole batch
};

struct BatchSettings {
  unsigned jobs = 1;        // worker threads (at least 1)
  bool keep_going = false;  // without: no new file is started after the first failure
  PostOptions post;
  bool verify = false;     // --verify: a program that does not cut its plan fails its file
  bool sheets = false;     // --sheets: a setup sheet next to each program (<stem>.html)
  std::string sheet_date;  // the date the sheets show (sheet_date())
};

// Where --sheets puts the sheet of the program `output`: beside it, <stem>.html.
std::string sheet_beside(const std::string& output);

// Posts every item with `settings.jobs` workers; one more thread publishes the programs they
// write (fsync and rename, many at a time: see PublishQueue in batch.cc). `on_result` is called
// once per item, in item order, from one thread at a time (items that were not posted come with
// kNotPosted), as soon as it and all items before it are done (a program: published). Returns
// every result, in item order.
std::vector<FileResult> run_batch(const std::vector<BatchItem>& items, const Machine& machine,
                                  const BatchSettings& settings,
                                  const std::function<void(const FileResult&)>& on_result);

BatchSummary summarize(const std::vector<FileResult>& results, double seconds);

// The per-file line for stderr, with its '\n':
//   `ok        in/a.cl`
//   `warnings  in/b.cl:5:1: warning: unknown statement 'FOO' written as a comment (+2 more)`
//   `error     in/c.cl:7:11: error: invalid number '-1.2.3'`
//   `skipped   in/d.cl (not posted after an earlier error; --keep-going posts it)`
std::string file_line(const FileResult& r);

// `3 files: 1 ok, 1 with warnings, 1 failed, 0 not posted; 1 error, 2 warnings; 1200 bytes in,
// 900 bytes out; 0.01 s` and a '\n'.
std::string summary_line(const BatchSummary& s);

// The progress bar drawn on a terminal: `[#####.....] 120/200 files, 3 failed`, no line end.
std::string progress_bar(size_t done, size_t total, size_t failed, size_t width = 30);

}  // namespace clpost
