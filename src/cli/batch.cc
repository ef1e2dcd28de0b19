#include "cli/batch.h"

#include "cli/sheet_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>
#include <utility>

namespace clpost {

namespace fs = std::filesystem;

bool is_cl_file_name(const std::string& name) {
  static constexpr std::string_view kExtensions[] = {".cl",   ".cls",       ".apt",   ".ncl",
                                                     ".clsf", ".aptsource", ".cldata"};
  const fs::path ext = fs::path(name).extension();
  std::string e = ext.string();
  for (char& c : e) c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  return std::find(std::begin(kExtensions), std::end(kExtensions), e) != std::end(kExtensions);
}

bool collect_inputs(const std::vector<std::string>& args, bool recursive,
                    std::vector<std::string>& files, std::string& error) {
  files.clear();
  for (const std::string& arg : args) {
    std::error_code ec;
    const fs::file_status st = fs::status(arg, ec);
    if (arg == "-") {
      error = "standard input ('-') cannot be posted in a batch";
      return false;
    }
    if (!fs::exists(st)) {
      error = fmt::format("{}: no such file or directory", arg);
      return false;
    }
    if (!fs::is_directory(st)) {
      files.push_back(arg);
      continue;
    }
    if (!recursive) {
      error = fmt::format("{}: is a directory (use -r to post the CL files in it)", arg);
      return false;
    }
    std::vector<std::string> found;
    fs::recursive_directory_iterator it(arg, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
      std::error_code fec;
      if (it->is_regular_file(fec) && is_cl_file_name(it->path().filename().string()))
        found.push_back(it->path().string());
    }
    if (ec) {
      error = fmt::format("{}: cannot read the directory: {}", arg, ec.message());
      return false;
    }
    if (found.empty()) {
      error = fmt::format("{}: no CL files in the directory", arg);
      return false;
    }
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return true;
}

bool plan_outputs(const std::vector<std::string>& files, const std::string& out_dir,
                  const std::string& extension, std::vector<BatchItem>& items, std::string& error) {
  items.clear();
  std::map<std::string, size_t> by_output;  // output path -> index of the input writing it
  for (const std::string& in : files) {
    std::string out = (fs::path(out_dir) / fs::path(in).stem()).string() + extension;
    auto [it, fresh] = by_output.emplace(out, items.size());
    if (!fresh) {
      error = fmt::format("'{}' and '{}' would both be written to '{}'", items[it->second].input,
                          in, out);
      return false;
    }
    items.push_back(BatchItem{in, std::move(out)});
  }
  return true;
}

std::string sheet_beside(const std::string& output) {
  return std::filesystem::path(output).replace_extension(".html").string();
}

namespace {

FileStatus status_of(const PostOutcome& o) {
  if (!o.ok) return FileStatus::kError;
  return o.warnings > 0 ? FileStatus::kWarnings : FileStatus::kOk;
}

// --sheets: the sheet of a posted file beside its program; a sheet that cannot be written fails
// the file (its program is not published).
void write_sheet(const BatchItem& item, const Machine& machine, const BatchSettings& settings,
                 SheetCapture& capture, FileResult& r) {
  const SheetInfo info{item.output, settings.sheet_date, SheetFormat::kHtml};
  std::string text, diagnostics;
  const std::string path = sheet_beside(item.output);
  if (sheet_text(item.input, r.outcome, capture, machine, info, text, diagnostics) &&
      write_text_file(path, text, diagnostics)) {
    r.sheet = path;
    return;
  }
  r.outcome.ok = false;
  ++r.outcome.errors;
  r.outcome.diagnostics += diagnostics;
  r.outcome.kept.push_back(
      Diagnostic{Severity::kError, {}, "the setup sheet: " + diagnostics, {}, 1, false});
}

// Posts one file; a good program is written out but left unpublished in `written`.
void post_one(const BatchItem& item, const Machine& machine, const BatchSettings& settings,
              FileResult& r, std::unique_ptr<OutputFile>& written) {
  const auto t0 = std::chrono::steady_clock::now();
  PostRequest req{item.input, item.output, &machine, settings.post, nullptr};
  req.verify = settings.verify;
  req.publish_later = [&written](std::unique_ptr<OutputFile> file) { written = std::move(file); };
  SheetCapture capture;
  if (settings.sheets) sheet_request(req, capture);
  r.outcome = post_file(req);
  if (settings.sheets && r.outcome.ok) {
    write_sheet(item, machine, settings, capture, r);
    if (!r.outcome.ok && written) {  // no program without its sheet
      written->abort();
      written.reset();
    }
  }
  r.status = status_of(r.outcome);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Programs written by the workers, waiting to be published. Publishing a program means fsync,
// then rename (so that a crash never leaves a part of a program under its name); one fsync per
// small program — a journal commit and a disk cache flush each — was most of a batch's time,
// with the workers queueing on the disk. Here the workers hand their programs over and go on
// posting, and one publisher thread publishes whatever has piled up since its last round, all
// at once (OutputFile::publish_all: one syncfs, then cheap fsyncs and the renames): the slower
// the disk, the larger the groups. A program is reported (`ok`) once published.
class PublishQueue {
 public:
  static constexpr size_t kMaxPending = 256;  // written, unpublished programs (open files)

  struct Entry {
    size_t index;  // in the batch
    std::unique_ptr<OutputFile> file;
  };

  // A worker: adds a written program (waits while too many are pending).
  void add(size_t index, std::unique_ptr<OutputFile> file) {
    std::unique_lock<std::mutex> lock(mu_);
    room_.wait(lock, [this] { return pending_.size() < kMaxPending; });
    pending_.push_back(Entry{index, std::move(file)});
    ready_.notify_one();
  }
  // No more programs will come.
  void close() {
    std::lock_guard<std::mutex> lock(mu_);
    closed_ = true;
    ready_.notify_one();
  }
  // The publisher: everything pending, once there is something; empty when closed and done.
  std::vector<Entry> next_group() {
    std::unique_lock<std::mutex> lock(mu_);
    ready_.wait(lock, [this] { return closed_ || !pending_.empty(); });
    std::vector<Entry> group = std::exchange(pending_, {});
    room_.notify_all();
    return group;
  }

 private:
  std::mutex mu_;
  std::condition_variable ready_;  // something to publish, or closed
  std::condition_variable room_;   // pending_ has room again
  std::vector<Entry> pending_;
  bool closed_ = false;
};

// The program of `r` could not be published: the file fails with that error.
void publish_failed(FileResult& r, const std::string& error) {
  const Diagnostic d{Severity::kError, SourceLoc{}, error, std::string()};
  r.outcome.diagnostics += Diagnostics(display_name(r.item.input)).render(d);
  r.outcome.kept.push_back(d);
  ++r.outcome.errors;
  r.outcome.ok = false;
  r.status = FileStatus::kError;
}

void publish_group(const std::vector<PublishQueue::Entry>& group,
                   std::vector<FileResult>& results) {
  std::vector<OutputFile*> files;
  for (const PublishQueue::Entry& e : group) files.push_back(e.file.get());
  std::vector<std::string> errors;
  OutputFile::publish_all(files, errors);
  for (size_t k = 0; k < group.size(); ++k)
    if (!errors[k].empty()) publish_failed(results[group[k].index], errors[k]);
}

// What the workers and the publisher share while a batch runs.
struct BatchRun {
  BatchRun(const std::vector<BatchItem>& items, const Machine& machine,
           const BatchSettings& settings, const std::function<void(const FileResult&)>& on_result)
      : items(items),
        machine(machine),
        settings(settings),
        on_result(on_result),
        results(items.size()),
        done(items.size(), 0) {
    for (size_t i = 0; i < items.size(); ++i) results[i].item = items[i];
  }

  const std::vector<BatchItem>& items;
  const Machine& machine;
  const BatchSettings& settings;
  const std::function<void(const FileResult&)>& on_result;
  std::vector<FileResult> results;
  std::vector<char> done;         // results[i] is final (posted and published, or failed)
  std::atomic<size_t> next{0};    // the next item to post
  std::atomic<bool> stop{false};  // a file failed (without --keep-going): post no more
  std::mutex mu;                  // guards done, reported and the calls of on_result
  size_t reported = 0;            // results[0, reported) were handed to on_result
  PublishQueue queue;
};

// With `mu` held: the results now final, up to the first that is not, to on_result (in the
// batch's order).
void report_ready(BatchRun& run) {
  while (run.reported < run.results.size() && run.done[run.reported]) {
    if (run.on_result) run.on_result(run.results[run.reported]);
    ++run.reported;
  }
}

// The publisher thread: publishes what the workers wrote, a group at a time, until the queue is
// closed and empty.
void publish_loop(BatchRun& run) {
  for (;;) {
    std::vector<PublishQueue::Entry> group = run.queue.next_group();
    if (group.empty()) return;
    publish_group(group, run.results);  // the slow part, without the lock
    std::lock_guard<std::mutex> lock(run.mu);
    for (const PublishQueue::Entry& e : group) {
      if (run.results[e.index].status == FileStatus::kError && !run.settings.keep_going)
        run.stop.store(true);
      run.done[e.index] = 1;
    }
    report_ready(run);
  }
}

// A worker thread: posts the next item nobody has taken, until there is none or the batch stops.
void work_loop(BatchRun& run) {
  for (;;) {
    if (run.stop.load()) return;
    const size_t i = run.next.fetch_add(1);
    if (i >= run.items.size()) return;
    FileResult& r = run.results[i];
    std::unique_ptr<OutputFile> written;
    post_one(run.items[i], run.machine, run.settings, r, written);
    if (written) {  // reported once published
      run.queue.add(i, std::move(written));
      continue;
    }
    if (r.status == FileStatus::kError && !run.settings.keep_going) run.stop.store(true);
    std::lock_guard<std::mutex> lock(run.mu);
    run.done[i] = 1;
    report_ready(run);
  }
}

}  // namespace

std::vector<FileResult> run_batch(const std::vector<BatchItem>& items, const Machine& machine,
                                  const BatchSettings& settings,
                                  const std::function<void(const FileResult&)>& on_result) {
  BatchRun run(items, machine, settings, on_result);
  const size_t jobs = std::clamp<size_t>(settings.jobs, 1, std::max<size_t>(items.size(), 1));
  std::thread publishing(publish_loop, std::ref(run));  // mostly waiting on the disk: not a job
  if (jobs == 1) {
    work_loop(run);
  } else {
    std::vector<std::thread> threads;
    threads.reserve(jobs);
    for (size_t t = 0; t < jobs; ++t) threads.emplace_back(work_loop, std::ref(run));
    for (std::thread& t : threads) t.join();
  }
  run.queue.close();
  publishing.join();
  // Items never started (the batch stopped after a failure) are reported as not posted.
  std::lock_guard<std::mutex> lock(run.mu);
  std::fill(run.done.begin(), run.done.end(), 1);
  report_ready(run);
  return std::move(run.results);
}

BatchSummary summarize(const std::vector<FileResult>& results, double seconds) {
  BatchSummary s;
  s.files = results.size();
  s.seconds = seconds;
  for (const FileResult& r : results) {
    switch (r.status) {
      case FileStatus::kOk:
        ++s.ok;
        break;
      case FileStatus::kWarnings:
        ++s.with_warnings;
        break;
      case FileStatus::kError:
        ++s.failed;
        break;
      case FileStatus::kNotPosted:
        ++s.not_posted;
        break;
    }
    s.errors += r.outcome.errors;
    s.warnings += r.outcome.warnings;
    s.bytes_in += r.outcome.bytes_in;
    if (r.outcome.ok) s.bytes_out += r.outcome.bytes_out;
  }
  return s;
}

namespace {

// The first line (`file:line:col: severity: message`) of the first kept diagnostic of a
// severity.
std::string first_diagnostic(const std::string& file, const PostOutcome& o, Severity sev) {
  const Diagnostics renderer(file);
  for (const Diagnostic& d : o.kept) {
    if (d.severity != sev) continue;
    std::string text = renderer.render(d);
    return text.substr(0, text.find('\n'));
  }
  return {};
}

std::string plural(size_t n, std::string_view one, std::string_view many) {
  return fmt::format("{} {}", n, n == 1 ? one : many);
}

}  // namespace

std::string file_line(const FileResult& r) {
  const PostOutcome& o = r.outcome;
  switch (r.status) {
    case FileStatus::kOk:
      return fmt::format("ok        {}\n", r.item.input);
    case FileStatus::kWarnings: {
      std::string first = first_diagnostic(r.item.input, o, Severity::kWarning);
      if (first.empty())
        first = fmt::format("{}: {}", r.item.input, plural(o.warnings, "warning", "warnings"));
      return fmt::format("warnings  {}{}\n", first,
                         o.warnings > 1 ? fmt::format(" (+{} more)", o.warnings - 1) : "");
    }
    case FileStatus::kError: {
      std::string first = first_diagnostic(r.item.input, o, Severity::kError);
      if (first.empty())
        first = fmt::format("{}: {}", r.item.input, plural(o.errors, "error", "errors"));
      return fmt::format("error     {}{}\n", first,
                         o.errors > 1 ? fmt::format(" (+{} more)", o.errors - 1) : "");
    }
    case FileStatus::kNotPosted:
      break;
  }
  return fmt::format("skipped   {} (not posted after an earlier error; --keep-going posts it)\n",
                     r.item.input);
}

std::string summary_line(const BatchSummary& s) {
  return fmt::format(
      "{}: {} ok, {} with warnings, {} failed, {} not posted; {}, {}; {} bytes in, {} bytes out; "
      "{:.2f} s\n",
      plural(s.files, "file", "files"), s.ok, s.with_warnings, s.failed, s.not_posted,
      plural(s.errors, "error", "errors"), plural(s.warnings, "warning", "warnings"), s.bytes_in,
      s.bytes_out, s.seconds);
}

std::string progress_bar(size_t done, size_t total, size_t failed, size_t width) {
  const size_t filled = total == 0 ? width : done * width / total;
  std::string bar(filled, '#');
  bar.append(width - filled, '.');
  return fmt::format("[{}] {}/{} files{}", bar, done, total,
                     failed ? fmt::format(", {} failed", failed) : "");
}

}  // namespace clpost
