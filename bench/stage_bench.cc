// Google Benchmark suite for the stages of the data flow: the reader (CL text to statements),
// the planner (a THREAD/ON sequence to a pass plan), the emitter (a plan to NC blocks), the
// writer (feed moves to NC blocks) and the whole post in memory. Throughput is reported as bytes
// and items (lines, plans, blocks) per second. The end-to-end figures on a file are bench/run.sh's.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "cl_generator.h"
#include "controls/registry.h"
#include "emitters/emitter.h"
#include "emitters/planner_settings.h"
#include "interpreter/post.h"
#include "machine/machine_loader.h"
#include "planner/planner.h"
#include "planner/thread_words.h"
#include "reader/cl_reader.h"
#include "reader/cldata_writer.h"
#include "support/sink.h"
#include "writer/nc_program.h"

namespace clpost {
namespace {

class CountingSink : public Sink {
 public:
  size_t bytes = 0;

 private:
  void overflow(std::string_view text) override { bytes += text.size(); }
};

const Machine& generic_lathe() {
  static const Machine m = [] {
    Machine out;
    std::string errors;
    if (!load_machine("generic-lathe", {CLPOST_SOURCE_DIR}, {}, shipped_controls(), out, errors))
      std::abort();
    return out;
  }();
  return m;
}

const std::string& turning_text() {
  static const std::string text = bench::turning_program_text(100000, 3000);
  return text;
}

size_t count_lines(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

void BM_Reader(benchmark::State& state) {
  const std::string& text = turning_text();
  size_t statements = 0;
  for (auto _ : state) {
    Diagnostics diags("bench.cl");
    ClReader reader(text, diags);
    Statement st;
    while (reader.next(st)) ++statements;
    benchmark::DoNotOptimize(statements);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * count_lines(text)));
}
BENCHMARK(BM_Reader)->Unit(benchmark::kMillisecond);

// The same program as binary CLDATA (APT360's records, 80 points to a motion record), through
// the same ClReader: bytes of the binary file, and statements, per second.
void BM_ReaderBinary(benchmark::State& state) {
  static const std::string bin = [] {
    Diagnostics diags("bench.cl");
    std::string out;
    if (!cldata::encode_apt(turning_text(), diags, out, {false, 80})) std::abort();
    return out;
  }();
  size_t statements = 0, per_pass = 0;
  for (auto _ : state) {
    Diagnostics diags("bench.cl");
    ClReader reader(bin, diags);
    Statement st;
    per_pass = 0;
    while (reader.next(st)) ++per_pass;
    statements += per_pass;
    benchmark::DoNotOptimize(statements);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * bin.size()));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * per_pass));
}
BENCHMARK(BM_ReaderBinary)->Unit(benchmark::kMillisecond);

// The THREAD/ON sequence of the benchmark program, ready for the planner.
MultiThreadInput thread_input() {
  const std::string text =
      "THREAD/ON,DEPTH,1.534,CUTS,4,FINCUT,1,0.1,OPTION,1,MMPR,2.5,CHAMFR,2.5\n"
      "GOTO/10,0,2\nGOTO/10,0,-30\n";
  Diagnostics diags("bench.cl");
  ClReader reader(text, diags);
  Statement st;
  MultiThreadInput in;
  reader.next(st);
  if (!parse_thread_words(st, 1, LengthUnit::kMm, in.words, diags)) std::abort();
  in.on_lines = SavedLines::of(st);
  in.on_loc = st.loc;
  in.p0 = Vec2{15, 5};
  while (reader.next(st))
    in.gotos.push_back(
        ThreadGoto{Vec2{st.args[0].number, st.args[2].number}, st.loc, SavedLines::of(st)});
  return in;
}

void BM_Planner(benchmark::State& state) {
  const MultiThreadInput in = thread_input();
  const PlannerSettings ps = planner_settings(generic_lathe());
  for (auto _ : state) {
    Diagnostics diags("bench.cl");
    ThreadPlan plan;
    if (!plan_multi_thread(in, ps, plan, diags)) std::abort();
    benchmark::DoNotOptimize(plan.passes.data());
  }
  state.SetItemsProcessed(state.iterations());  // plans
}
BENCHMARK(BM_Planner);

void BM_Emitter(benchmark::State& state) {
  const Machine& m = generic_lathe();
  const MultiThreadInput in = thread_input();
  Diagnostics diags("bench.cl");
  ThreadPlan plan;
  if (!plan_multi_thread(in, planner_settings(m), plan, diags)) std::abort();
  std::unique_ptr<Emitter> emitter = make_emitter(m);
  CountingSink sink;
  for (auto _ : state) {
    NcProgram prog(m, sink);
    EmitContext ctx{diags, in.on_lines, 600, 0.2, FeedMode::kPerRev};
    emitter->emit(plan, prog, ctx);
  }
  state.SetBytesProcessed(static_cast<int64_t>(sink.bytes));
  state.SetItemsProcessed(state.iterations());  // threads
}
BENCHMARK(BM_Emitter);

void BM_WriterFeedMoves(benchmark::State& state) {
  const Machine& m = generic_lathe();
  CountingSink sink;
  NcProgram prog(m, sink);
  prog.set_feed(0.25, FeedMode::kPerRev);
  size_t i = 0;
  for (auto _ : state) {
    const double k = static_cast<double>(i++ % 200);
    prog.linear(LathePoint{19.0 - 0.0125 * static_cast<double>(i % 13), 1.0 - 0.4173 * k});
  }
  state.SetBytesProcessed(static_cast<int64_t>(sink.bytes));
  state.SetItemsProcessed(state.iterations());  // blocks
}
BENCHMARK(BM_WriterFeedMoves);

void BM_PostInMemory(benchmark::State& state) {
  const Machine& m = generic_lathe();
  const std::string& text = turning_text();
  for (auto _ : state) {
    CountingSink sink;
    Diagnostics diags("bench.cl");
    ClReader reader(text, diags);
    post(reader, m, sink, diags);
    if (diags.has_errors()) std::abort();
    benchmark::DoNotOptimize(sink.bytes);
  }
  state.SetBytesProcessed(static_cast<int64_t>(state.iterations() * text.size()));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * count_lines(text)));
}
BENCHMARK(BM_PostInMemory)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace clpost

BENCHMARK_MAIN();
