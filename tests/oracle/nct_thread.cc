// The NCT dialect of the Fanuc/Haas reader (fanuc_reader.h, Dialect::kNct): G33's lead and start
// angle, and F outside G33. What NCT shares with the others is read by fanuc_reader.cc, each
// difference beside its code there. Sources:
//   [seed 002] ../shared/reference/seeds/002_… (NCT 99M/2000M manual, "Equal Lead Thread
//              Cutting (G33)"), and controllers.md's "NCT 99M / 2000M" summary of it.
//   [99M]      NCT 99M / 2000M Controls for Milling Machines and Machining Centers, Programmer's
//              Manual, by section: "Inch/Metric Conversion (G20, G21)", "Specification and Value
//              Range of Coordinate Data" (IS-B; "X325 means e.g. 325 mm"), "Constant Surface Speed
//              Control Command (G96, G97)" (G94 is feed per minute), "Constant Surface Speed
//              Clamp (G92)", "Conditional Block Skip"; G90 "absolute data specification" (its
//              introduction). NCT's lathe manual (101T/104T/115T) was not found beyond its
//              contents: the family's meanings are taken as the lathe's.
//   [ISO]      ISO 6983-1 (G95 feed per revolution beside G94, M3/M4/M5, M7/M8/M9, M30): the
//              NCT sources found name G94 and M3/M8 only.
// Assumptions (docs/cl-meaning.md, "How the oracle reads an NCT program"): G4 X<seconds> and
// T<tool><offset> as Fanuc's, the plain ISO program frame (%, O, N, comments in parentheses).
#include <cmath>

#include "fanuc_reader_impl.h"

namespace oracle::fanuc_detail {

// F outside G33 is the feed in the mode in force (G94 per minute [99M], G95 per revolution [ISO]);
// in a G33 block it is the lead in mm/rev or inch/rev [seed 002]. Whether G33's F is also the
// feed afterwards is not documented: a feed move after it must give its own F (motion()).
bool Control::nct_feed(const Word& f) {
  if (motion_ == 33) {
    lead_ = f.value * unit();
    f_is_lead_ = true;
  } else {
    f_ = f.value, f_given_ = true;
    f_is_lead_ = false;
  }
  return true;
}

// [seed 002] "G33 v F Q / G33 v E Q": F the lead (mm/rev or inch/rev), or E the threads per inch
// of an inch thread ("E3 … a 25.4/3 = 8.4667 mm lead", in either unit); the lead is taken along
// the longer axis (Z below 45°), as the events' lead is. Q the start angle in degrees from the
// encoder's zero pulse, taken into account in the first block only: "G33 is a modal function",
// successive G33 blocks make one continuous thread, synchronised in the first block and not in
// the others, so a Q there has no meaning the manual gives: refused.
bool Control::nct_lead(const Block& b, Event& e) {
  const Word *f = b.find('F'), *tpi = b.find('E'), *q = b.find('Q');
  if ((f != nullptr) == (tpi != nullptr)) return fail("G33 needs one of F (lead) and E (TPI)");
  if (tpi && !(tpi->value > 0)) return fail("G33 E that is not a number of threads per inch");
  if (q && thread_chain_) return fail("Q in a G33 block that continues a thread");
  if (q && (q->value < 0 || q->value >= 360)) return fail("G33 Q outside 0-360 degrees");
  e.lead = f ? lead_ : kMmPerInch / tpi->value;
  thread_chain_ = true;
  return true;
}

}  // namespace oracle::fanuc_detail
