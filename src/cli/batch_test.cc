// The batch's pieces: input expansion, output names, per-file lines, the summary and the report.
// The whole command is tested through the binary in tests/batch_test.cc.
#include "cli/batch.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "cli/batch_report.h"
#include "controls/registry.h"
#include "machine/machine_loader.h"

namespace clpost {
namespace {

namespace fs = std::filesystem;

class TempDir {
 public:
  TempDir() {
    std::string templ = (fs::temp_directory_path() / "clpost-batch-XXXXXX").string();
    path_ = ::mkdtemp(templ.data());
  }
  ~TempDir() { fs::remove_all(path_); }
  const std::string& path() const { return path_; }
  std::string touch(const std::string& rel) const {
    fs::path p = fs::path(path_) / rel;
    fs::create_directories(p.parent_path());
    std::FILE* f = std::fopen(p.c_str(), "w");
    std::fputs("FINI\n", f);
    std::fclose(f);
    return p.string();
  }

 private:
  std::string path_;
};

TEST(BatchInputs, FilesAreTakenAsGivenInOrder) {
  TempDir d;
  std::string b = d.touch("b.txt"), a = d.touch("a.cl");
  std::vector<std::string> files;
  std::string err;
  ASSERT_TRUE(collect_inputs({b, a}, false, files, err)) << err;
  EXPECT_EQ(files, (std::vector<std::string>{b, a}));
}

TEST(BatchInputs, DirectoriesNeedRecursiveAndYieldSortedClFiles) {
  TempDir d;
  d.touch("z.cl");
  d.touch("sub/y.APT");
  d.touch("sub/deeper/x.cls");
  d.touch("notes.txt");
  d.touch("sub/part.nc");
  std::vector<std::string> files;
  std::string err;
  EXPECT_FALSE(collect_inputs({d.path()}, false, files, err));
  EXPECT_EQ(err, d.path() + ": is a directory (use -r to post the CL files in it)");
  ASSERT_TRUE(collect_inputs({d.path()}, true, files, err)) << err;
  EXPECT_EQ(files, (std::vector<std::string>{d.path() + "/sub/deeper/x.cls",
                                             d.path() + "/sub/y.APT", d.path() + "/z.cl"}));
}

TEST(BatchInputs, MissingInputsAndEmptyDirectoriesAreErrors) {
  TempDir d;
  std::vector<std::string> files;
  std::string err;
  EXPECT_FALSE(collect_inputs({d.path() + "/nope.cl"}, false, files, err));
  EXPECT_EQ(err, d.path() + "/nope.cl: no such file or directory");
  d.touch("only.txt");
  EXPECT_FALSE(collect_inputs({d.path()}, true, files, err));
  EXPECT_EQ(err, d.path() + ": no CL files in the directory");
  EXPECT_FALSE(collect_inputs({"-"}, false, files, err));
}

TEST(BatchInputs, ClFileNames) {
  EXPECT_TRUE(is_cl_file_name("a.cl"));
  EXPECT_TRUE(is_cl_file_name("dir.x/A.CLS"));
  EXPECT_TRUE(is_cl_file_name("p.aptsource"));
  EXPECT_TRUE(is_cl_file_name("b.ncl"));
  EXPECT_FALSE(is_cl_file_name("a.nc"));
  EXPECT_FALSE(is_cl_file_name("cl"));
  EXPECT_FALSE(is_cl_file_name("a.cl.bak"));
}

TEST(BatchOutputs, StemPlusMachineExtension) {
  std::vector<BatchItem> items;
  std::string err;
  ASSERT_TRUE(plan_outputs({"in/a.cl", "x/b.part.apt"}, "out", ".ngc", items, err));
  ASSERT_EQ(items.size(), 2u);
  EXPECT_EQ(items[0].output, "out/a.ngc");
  EXPECT_EQ(items[1].output, "out/b.part.ngc");
}

TEST(BatchOutputs, DuplicateStemsAreRefused) {
  std::vector<BatchItem> items;
  std::string err;
  EXPECT_FALSE(plan_outputs({"a/part.cl", "c.cl", "b/part.apt"}, "out", ".nc", items, err));
  EXPECT_EQ(err, "'a/part.cl' and 'b/part.apt' would both be written to 'out/part.nc'");
}

// Programs are published in groups (one syncfs per group): with more files than a group holds,
// every program is there after the batch, results come in input order, a failing file in the
// middle fails alone (--keep-going), and no temporary file is left.
TEST(BatchRun, ProgramsArePublishedInGroups) {
  Machine m;
  std::string errors;
  ASSERT_TRUE(load_machine("generic-lathe", {CLPOST_SOURCE_DIR}, {}, shipped_controls(), m, errors))
      << errors;
  for (unsigned jobs : {1u, 2u}) {
    TempDir d;
    std::vector<std::string> files;
    for (int i = 0; i < 75; ++i) {
      const std::string name = fmt::format("in/p{:02}.cl", i);
      files.push_back(d.touch(name));
      std::FILE* f = std::fopen(files.back().c_str(), "w");
      std::fputs(i == 40 ? "GOTO/1,2,\nFINI\n" : "RAPID\nGOTO/1,0,2\nFINI\n", f);
      std::fclose(f);
    }
    std::vector<BatchItem> items;
    std::string err;
    ASSERT_TRUE(plan_outputs(files, d.path() + "/out", ".nc", items, err)) << err;
    fs::create_directories(d.path() + "/out");
    BatchSettings settings;
    settings.jobs = jobs;
    settings.keep_going = true;
    std::vector<std::string> reported;
    std::vector<FileResult> results = run_batch(items, m, settings, [&](const FileResult& r) {
      reported.push_back(r.item.input);
      EXPECT_EQ(fs::exists(r.item.output), r.status != FileStatus::kError) << r.item.input;
    });
    EXPECT_EQ(reported, files);  // in input order
    ASSERT_EQ(results.size(), 75u);
    for (size_t i = 0; i < results.size(); ++i) {
      const bool bad = i == 40;
      EXPECT_EQ(results[i].status, bad ? FileStatus::kError : FileStatus::kOk) << i;
      EXPECT_EQ(fs::exists(items[i].output), !bad) << i;
    }
    EXPECT_EQ(static_cast<size_t>(std::distance(fs::directory_iterator(d.path() + "/out"),
                                                fs::directory_iterator())),
              74u);  // no temporary file left
  }
}

FileResult result(FileStatus st, size_t errors, size_t warnings, std::vector<Diagnostic> kept) {
  FileResult r;
  r.item = BatchItem{"in/p.cl", "out/p.nc"};
  r.status = st;
  r.outcome.ok = st != FileStatus::kError;
  r.outcome.errors = errors;
  r.outcome.warnings = warnings;
  r.outcome.kept = std::move(kept);
  r.outcome.bytes_in = 100;
  r.outcome.bytes_out = 80;
  return r;
}

TEST(BatchLines, OneLinePerFileWithTheFirstDiagnostic) {
  Diagnostic note{Severity::kNote, {2, 1}, "a note", "X"};
  Diagnostic warn{Severity::kWarning, {5, 1}, "unknown statement 'FOO'", "FOO"};
  Diagnostic err{Severity::kError, {7, 11}, "invalid number '-1.2.3'", "GOTO/10,0,-1.2.3"};
  EXPECT_EQ(file_line(result(FileStatus::kOk, 0, 0, {note})), "ok        in/p.cl\n");
  EXPECT_EQ(file_line(result(FileStatus::kWarnings, 0, 3, {note, warn})),
            "warnings  in/p.cl:5:1: warning: unknown statement 'FOO' (+2 more)\n");
  EXPECT_EQ(file_line(result(FileStatus::kError, 1, 1, {warn, err})),
            "error     in/p.cl:7:11: error: invalid number '-1.2.3'\n");
  EXPECT_EQ(file_line(result(FileStatus::kNotPosted, 0, 0, {})),
            "skipped   in/p.cl (not posted after an earlier error; --keep-going posts it)\n");
}

TEST(BatchLines, Summary) {
  std::vector<FileResult> rs = {result(FileStatus::kOk, 0, 0, {}),
                                result(FileStatus::kWarnings, 0, 2, {}),
                                result(FileStatus::kError, 1, 0, {})};
  BatchSummary s = summarize(rs, 0.25);
  EXPECT_EQ(s.files, 3u);
  EXPECT_EQ(s.bytes_in, 300u);
  EXPECT_EQ(s.bytes_out, 160u);  // the failed file wrote nothing
  EXPECT_EQ(summary_line(s),
            "3 files: 1 ok, 1 with warnings, 1 failed, 0 not posted; 1 error, 2 warnings; "
            "300 bytes in, 160 bytes out; 0.25 s\n");
}

TEST(BatchLines, ProgressBar) {
  EXPECT_EQ(progress_bar(0, 4, 0, 8), "[........] 0/4 files");
  EXPECT_EQ(progress_bar(2, 4, 1, 8), "[####....] 2/4 files, 1 failed");
  EXPECT_EQ(progress_bar(4, 4, 0, 8), "[########] 4/4 files");
}

TEST(BatchReport, Json) {
  Diagnostic err{Severity::kError, {7, 11}, "invalid number '-1.2.3' \"q\"", "GOTO/10,0,-1.2.3"};
  std::vector<FileResult> rs = {result(FileStatus::kOk, 0, 0, {}),
                                result(FileStatus::kError, 1, 0, {err})};
  rs[0].outcome.stats.threads = 2;
  rs[0].outcome.stats.passes = 9;
  rs[0].outcome.stats.statements = 12;
  rs[0].outcome.stats.motions = 7;
  rs[0].seconds = 0.5;
  rs[0].sheet = "out/p.html";  // --sheets: the report links the program's sheet
  BatchSummary s = summarize(rs, 1.5);
  EXPECT_EQ(batch_report_json(BatchReportInfo{"generic-lathe", "out", 2}, s, rs),
            R"({
  "machine": "generic-lathe",
  "output_dir": "out",
  "jobs": 2,
  "summary": {"files": 2, "ok": 1, "with_warnings": 0, "failed": 1, "not_posted": 0, "errors": 1, "warnings": 0, "bytes_in": 200, "bytes_out": 80, "seconds": 1.500000},
  "files": [
    {"input": "in/p.cl", "output": "out/p.nc", "status": "ok", "errors": 0, "warnings": 0, "statements": 12, "motions": 7, "threads": 2, "passes": 9, "bytes_in": 100, "bytes_out": 80, "seconds": 0.500000, "cycle_time": {"seconds": 0.000, "rapids_timed": true, "tools": []}, "sheet": "out/p.html", "diagnostics": []},
    {"input": "in/p.cl", "output": null, "status": "error", "errors": 1, "warnings": 0, "statements": 0, "motions": 0, "threads": 0, "passes": 0, "bytes_in": 100, "bytes_out": 0, "seconds": 0.000000, "cycle_time": null, "sheet": null, "diagnostics": [
      {"severity": "error", "line": 7, "column": 11, "message": "invalid number '-1.2.3' \"q\""}
    ]}
  ]
}
)");
}

}  // namespace
}  // namespace clpost
