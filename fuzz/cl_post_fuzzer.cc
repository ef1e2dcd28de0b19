// libFuzzer target: arbitrary bytes as a CL file, through the reader, the interpreter, the
// thread planner, the emitters and the NC writer, on one of the shipped machines (picked by the
// first byte's high bits), read from memory or through a FILE* (the first byte's second bit), so
// both LineSource paths are covered: each input costs one post.
//
// With CLPOST_FUZZ_ROUND_TRIP=1 in the environment (scripts/fuzz.sh --round-trip), the first
// byte's third bit asks for the round trip instead: the file posted on the machine the byte's
// high bits pick and, when it posts without an error, its program read back through the control
// simulation and verified against the CL — its threads, holes, motions, arcs, tool, feed and
// spindle. A program clpost wrote without an error that does
// not verify is a bug in one or the other: the run stops on it, with both sides' words. (A file
// that passes the user's own words to the program, INSERT, AUXFUN or PREFUN, is not verified:
// those words may stop the spindle or change the feed mode, as the user meant.)
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "fuzz_post.h"
#include "verify/program_verify.h"

namespace {

std::vector<clpost::Machine>* g_machines = nullptr;  // every shipped machine
bool g_round_trip = false;                           // CLPOST_FUZZ_ROUND_TRIP=1

// The words whose text clpost passes to the program as the user wrote it (INSERT, AUXFUN's M
// code, PREFUN's G code): what they do to the control is the user's, not the post's to know.
bool passes_raw_words(std::string_view text) {
  std::string upper(text);
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const char* word : {"INSERT", "AUXFUN", "PREFUN"})
    if (upper.find(word) != std::string::npos) return true;
  return false;
}

// Posts `text` on `m` and verifies the program against it; aborts when a clean post does not
// verify. Files with raw words are only posted.
void round_trip(std::string_view text, const clpost::Machine& m, bool strict) {
  using namespace clpost;
  if (passes_raw_words(text)) return;
  Diagnostics diags("fuzz.cl");
  ClReader reader(text, diags);
  PostOptions opts;
  opts.strict = strict;
  opts.keep_motions = true;
  StringSink sink;
  std::vector<ThreadPlan> plans;
  PostSummary summary =
      post(reader, m, sink, diags, opts, [&](const ThreadPlan& p) { plans.push_back(p); });
  if (diags.has_errors()) return;
  const ClExpected expected{std::move(summary.holes), std::move(summary.path),
                            std::move(summary.mill)};
  reader::LineSource src{std::string_view(sink.out)};
  const VerifyOutcome v = verify_program(src, "fuzz.nc", plans, &expected, "fuzz.cl", m, 0);
  if (v.ok) return;
  std::fprintf(stderr, "round trip on %s: the program clpost wrote does not verify\n%s%s\n%s\n",
               m.name.c_str(), v.report.c_str(), v.diagnostics.c_str(), sink.out.c_str());
  std::abort();
}

}  // namespace

// The machines are loaded once, before the first input (a machine that does not load stops the
// run here, not in the middle of it).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_machines = new std::vector<clpost::Machine>(clpost::fuzz::shipped_machines());
  const char* round_trip = std::getenv("CLPOST_FUZZ_ROUND_TRIP");
  g_round_trip = round_trip != nullptr && std::string_view(round_trip) == "1";
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace clpost;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The first byte's low bit picks --strict (the text still starts at byte 0).
  PostOptions opts;
  opts.strict = size > 0 && (data[0] & 1) != 0;
  const Machine& m = (*g_machines)[size > 0 ? (data[0] >> 3) % g_machines->size() : 0];
  if (g_round_trip && size > 0 && (data[0] & 4) != 0) {
    round_trip(text, m, opts.strict);
  } else if (size == 0 || (data[0] & 2) == 0) {
    Diagnostics diags("fuzz.cl");
    ClReader reader(text, diags);
    fuzz::post(reader, diags, m, opts);
  } else {
    std::FILE* f = fmemopen(const_cast<uint8_t*>(data), size, "rb");
    if (f != nullptr) {
      Diagnostics diags("fuzz.cl");
      ClReader reader(f, diags);
      fuzz::post(reader, diags, m, opts);
      std::fclose(f);
    }
  }
  return 0;
}
