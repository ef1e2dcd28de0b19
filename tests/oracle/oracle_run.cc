// The differential test from the command line (scripts/fuzz.sh --oracle runs it):
//   oracle_run --seed N               one program: its CL, NC, events and first difference
//   oracle_run --seconds S [--from N] fresh seeds from N (default: the clock) for S seconds
//   oracle_run --count C [--from N]   C programs from seed N (default 1)
//   oracle_run --control fanuc|haas|heidenhain|nct|sinumerik --read P.nc   a program's events as
//   the
//                                     oracle's reader reads them (block delete off), or where it
//                                     stops (heidenhain: read in mm, control parameter 1)
//   … --machine M                     another shipped machine of the control (fanuc-0i-tf-live,
//                                     haas-st-20y)
//   … --control linuxcnc|fanuc|haas|heidenhain|nct|sinumerik   the control (default linuxcnc):
//                                     linuxcnc-lathe run by rs274, fanuc-0i-t, haas-st,
//                                     heidenhain-pilot, nct-2000t or sinumerik-840d read by the
//                                     oracle's reader
// Prints the count, the classes of difference with their first seed and the first program that
// differs in full; exit status 1 when any program differs, 2 on a usage error.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "differential.h"
#include "fanuc_reader.h"
#include "heidenhain_reader.h"
#include "sinumerik_reader.h"

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: oracle_run --seed N | --seconds S [--from N] | --count C [--from N]"
               " [--control linuxcnc|fanuc|haas|heidenhain|nct|sinumerik] [--machine M]\n");
  return 2;
}

int one(oracle::Differential& d, uint32_t seed) {
  const oracle::ProgramResult r = d.check(seed);
  if (!r.differs && !r.refused) {
    std::printf("seed %u: the program does what the CL says\n--- CL\n%s--- NC\n%s", seed,
                r.cl.c_str(), r.nc.c_str());
    for (const oracle::Event& e : r.model) std::printf("  %s\n", oracle::describe(e).c_str());
    return 0;
  }
  std::printf("%s%s", r.refused ? "refused by clpost (not a difference):\n" : "",
              oracle::report(r).c_str());
  return r.differs ? 1 : 0;
}

// The reader's events of the program in `path`.
int read(oracle::Control control, const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f || control == oracle::Control::kLinuxcnc) return usage();
  std::string text;
  char buf[4096];
  for (size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
  std::fclose(f);
  const oracle::ControlRun r = control == oracle::Control::kHeidenhain
                                   ? oracle::heidenhain_events(text, false, false)
                               : control == oracle::Control::kSinumerik
                                   ? oracle::sinumerik_events(text, false)
                                   : oracle::fanuc_events(text, oracle::dialect_of(control), false);
  for (const oracle::Event& e : r.events) std::printf("%s\n", oracle::describe(e).c_str());
  if (r.error.empty()) return 0;
  std::printf("stops at line %d: %s\n", r.error_line, r.error.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 0;
  int count = 0;
  long long seed = -1, from = -1;
  std::string read_path, machine;
  oracle::Control control = oracle::Control::kLinuxcnc;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--seed")
      seed = std::atoll(argv[i + 1]);
    else if (a == "--seconds")
      seconds = std::atof(argv[i + 1]);
    else if (a == "--count")
      count = std::atoi(argv[i + 1]);
    else if (a == "--from")
      from = std::atoll(argv[i + 1]);
    else if (a == "--machine")
      machine = argv[i + 1];
    else if (a == "--read")
      read_path = argv[i + 1];
    else if (a == "--control" && oracle::control_named(argv[i + 1], control))
      continue;
    else
      return usage();
  }
  if (!read_path.empty()) return read(control, read_path);
  if (argc % 2 == 0 || (seed < 0 && seconds <= 0 && count <= 0)) return usage();
  if (control == oracle::Control::kLinuxcnc && !oracle::rs274_installed()) {
    std::fprintf(stderr, "oracle_run: rs274 not installed (apt-get install linuxcnc-uspace)\n");
    return 2;
  }
  oracle::Differential d;
  std::string error;
  if (!d.init(CLPOST_SOURCE_DIR, error, control, machine)) {
    std::fprintf(stderr, "oracle_run: %s\n", error.c_str());
    return 2;
  }
  if (seed >= 0) return one(d, static_cast<uint32_t>(seed));
  if (from < 0)
    from = seconds > 0 ? std::chrono::system_clock::now().time_since_epoch() /
                             std::chrono::seconds(1) % 1000000000
                       : 1;
  const oracle::Summary s = d.run(static_cast<uint32_t>(from), count, seconds);
  std::printf("seeds %lld to %lld\n%s", from, from + s.programs - 1,
              oracle::summary_text(s).c_str());
  if (!s.firsts.empty())  // the first program that differs; any other: --seed N
    std::printf("\nthe first program that differs:\n%s", oracle::report(s.firsts[0]).c_str());
  return s.differing > 0 ? 1 : 0;
}
