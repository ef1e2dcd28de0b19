#pragma once
// Deterministic benchmark CL text (no clock, no random seed): a turning program of roughing
// passes (RAPID in, up to 200 feed moves along Z with a small X wobble, retract) with a THREAD/ON
// sequence every `thread_every` GOTO lines. Used by gen_cl (files) and clpost_bench (memory).
#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <string>
#include <string_view>

namespace clpost::bench {

// Appends the program to `buf`, calling `flush(buf)` (which empties it) whenever it holds more
// than about 1 MiB, so that a file of any size is written in bounded memory.
template <typename Flush>
void turning_program(std::string& buf, Flush&& flush, std::string_view name, long gotos,
                     long thread_every) {
  auto out = std::back_inserter(buf);
  auto maybe_flush = [&] {
    if (buf.size() > (1 << 20)) flush(buf);
  };
  fmt::format_to(out, "$$ clpost benchmark: {} GOTO lines\nPARTNO {}\n", gotos, name);
  buf += "UNITS/MM\nLOADTL/1,ADJUST,1\nSPINDL/1200,RPM,CLW\nCOOLNT/FLOOD\nFEDRAT/0.25,MMPR\n";
  buf += "RAPID\nGOTO/40.0000,0.0000,5.0000\n";
  long written = 1;
  long pass = 0;
  long since_thread = 0;
  while (written < gotos) {
    if (thread_every > 0 && since_thread >= thread_every) {
      since_thread = 0;
      buf +=
          "LOADTL/7,ADJUST,7\nSPINDL/600,RPM,CLW\nRAPID\nGOTO/15.0000,0.0000,5.0000\n"
          "THREAD/ON,DEPTH,1.534,CUTS,4,FINCUT,1,0.1,OPTION,1,MMPR,2.5,CHAMFR,2.5\n"
          "GOTO/10.0000,0.0000,2.0000\nGOTO/10.0000,0.0000,-30.0000\nTHREAD/OFF\n"
          "LOADTL/1,ADJUST,1\nSPINDL/1200,RPM,CLW\nFEDRAT/0.25,MMPR\n";
      written += 3;
      continue;
    }
    const double x = 38.0 - static_cast<double>(pass % 80) * 0.35;
    fmt::format_to(out, "RAPID\nGOTO/{:.4f},0.0000,2.0000\n", x);
    ++written;
    const long moves = std::min<long>(200, gotos - written);
    for (long i = 0; i < moves; ++i) {
      const double z = 1.0 - static_cast<double>(i) * 0.4173;
      const double xi = x - 0.0125 * static_cast<double>((i * 7 + pass) % 13);
      fmt::format_to(out, "GOTO/{:.4f},0.0000,{:.4f}\n", xi, z);
    }
    written += moves;
    since_thread += moves + 1;
    if (written < gotos) {
      fmt::format_to(out, "GOTO/{:.4f},0.0000,-82.0000\n", x + 1.0);
      ++written;
    }
    ++pass;
    maybe_flush();
  }
  buf += "RAPID\nGOTO/50.0000,0.0000,50.0000\nCOOLNT/OFF\nSPINDL/OFF\nEND\nFINI\n";
  flush(buf);
}

// `count` identical multi-pass threads (THREAD/ON with 4 cuts and a finish), one after the other,
// each from a rapid approach: the plot and verify of many threads.
template <typename Flush>
void threads_program(std::string& buf, Flush&& flush, std::string_view name, long count) {
  fmt::format_to(std::back_inserter(buf), "$$ clpost benchmark: {} threads\nPARTNO {}\n", count,
                 name);
  buf += "UNITS/MM\nLOADTL/7,ADJUST,7\nSPINDL/600,RPM,CLW\nCOOLNT/FLOOD\nFEDRAT/0.25,MMPR\n";
  for (long n = 0; n < count; ++n) {
    buf +=
        "RAPID\nGOTO/15.0000,0.0000,5.0000\n"
        "THREAD/ON,DEPTH,1.534,CUTS,4,FINCUT,1,0.1,OPTION,1,MMPR,2.5,CHAMFR,2.5\n"
        "GOTO/10.0000,0.0000,2.0000\nGOTO/10.0000,0.0000,-30.0000\nTHREAD/OFF\n";
    if (buf.size() > (1 << 20)) flush(buf);
  }
  buf += "RAPID\nGOTO/50.0000,0.0000,50.0000\nCOOLNT/OFF\nSPINDL/OFF\nEND\nFINI\n";
  flush(buf);
}

// A live tool's face milling (docs/millturn.md), `gotos` GOTO lines: a square 20 x 20 around the
// centre at C index 30, cut at depths that step down and start again, each pass from a rapid up
// to above its corner (a real move: a RAPID to where the tool already is has no program move);
// then a turning tool's rapid. For a machine with C (linuxcnc-lathe-c): verify's memory.
template <typename Flush>
void milling_program(std::string& buf, Flush&& flush, std::string_view name, long gotos) {
  auto out = std::back_inserter(buf);
  fmt::format_to(out, "$$ clpost benchmark: {} milling GOTO lines\nPARTNO {}\n", gotos, name);
  buf += "UNITS/MM\nLOADTL/3,MILL\nSPINDL/3000,RPM,CLW\nROTABL/30,CAXIS\nFEDRAT/200,MMPM\n";
  static constexpr double kCorners[4][2] = {{10, 10}, {-10, 10}, {-10, -10}, {10, -10}};
  long written = 0;
  for (long pass = 0; written < gotos; ++pass) {
    const double z = -0.1 - 0.1 * static_cast<double>(pass % 20);
    buf += "RAPID\nGOTO/10.0000,-10.0000,5.0000\n";
    fmt::format_to(out, "GOTO/10.0000,-10.0000,{:.4f}\n", z);
    written += 2;
    for (long i = 0; i < 4 && written < gotos; ++i, ++written)
      fmt::format_to(out, "GOTO/{:.4f},{:.4f},{:.4f}\n", kCorners[i][0], kCorners[i][1], z);
    if (buf.size() > (1 << 20)) flush(buf);
  }
  buf += "SPINDL/OFF\nLOADTL/1,TURN\nSPINDL/1000,RPM,CLW\nRAPID\nGOTO/22,0,2\nEND\nFINI\n";
  flush(buf);
}

// The whole program in memory (benchmarks of small inputs).
inline std::string turning_program_text(long gotos, long thread_every) {
  std::string all, buf;
  turning_program(
      buf,
      [&](std::string& b) {
        all += b;
        b.clear();
      },
      "BENCH", gotos, thread_every);
  return all;
}

}  // namespace clpost::bench
