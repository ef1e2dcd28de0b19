#pragma once
// The words of a thread statement as written: THREAD/ON parameters (also the Pro/E form
// `OP/THREAD,TURN,...`) and the pitch couplets of PITCH/, COUPLE/ON and THREAD/TURN|FACE|TAPER.
// Values are converted to CL units here; what they mean for the cut is decided by the planner
// (planner.h). Every parameter keeps the location of its keyword so that later errors point at
// the right column.
#include <cstddef>
#include <string_view>
#include <vector>

#include "planner/thread_plan.h"
#include "reader/statement.h"
#include "support/diagnostics.h"

namespace clpost {

// Pitch couplets as written on one statement. Each part replaces the modal PITCH/ state only when
// it was given (THREAD/ON,MULTRD,2 keeps the modal pitch and cuts two starts).
struct PitchWords {
  bool value_given = false;  // TPI, IPR, MMPR, PERREV or (PITCH/ only) a leading value
  double pitch = 0;          // CL units
  bool from_tpi = false;
  double tpi = 0;
  SourceLoc value_loc;

  bool starts_given = false;  // MULTRD
  int starts = 1;
  SourceLoc starts_loc;

  bool change_given = false;  // INCR / DECR
  double lead_change = 0;     // CL units per revolution, + for INCR, - for DECR
  SourceLoc change_loc;

  bool any() const { return value_given || starts_given || change_given; }
  // Overrides the parts of `spec` that were given.
  void apply_to(PitchSpec& spec) const;
};

// A keyword with one value.
template <typename T>
struct ThreadParam {
  bool set = false;
  T value{};
  SourceLoc loc;  // of the keyword
};

// `count` passes stepping `step` (one couplet of CUTS).
struct CutSteps {
  int count = 0;
  double step = 0;
  SourceLoc loc;  // of the count
};

// CUTS,c (count only) / CUTS,c,s (one couplet) / CUTS,n1,s1,n2,s2,... (couplets).
struct CutsParam {
  bool set = false;
  SourceLoc loc;
  int count = 0;                // total number of passes the CUTS word asks for
  std::vector<CutSteps> steps;  // empty for the count-only form
};

// FINCUT,count[,dist].
struct FincutParam {
  bool set = false;
  SourceLoc loc;
  int count = 0;    // finish passes at full depth
  double dist = 0;  // finish allowance
};

// ATANGL,alpha[,h]. h = 0 (or omitted) means the default height pitch/(2 tan 30).
struct AtanglParam {
  bool set = false;
  SourceLoc loc;
  double angle = 0;
  double height = 0;
};

// CHAMFR,L[,beta]. L = 0 means no chamfer.
struct ChamfrParam {
  bool set = false;
  SourceLoc loc;
  double length = 0;
  bool angle_given = false;
  double angle = 45;
};

// RETURN[,h].
struct ReturnParam {
  bool set = false;
  SourceLoc loc;
  bool height_given = false;
  double height = 0;
};

// The parameters of THREAD/ON (lengths in CL units, angles in degrees).
struct ThreadWords {
  ThreadParam<double> depth;   // DEPTH,D (D > 0)
  CutsParam cuts;              // CUTS
  ThreadParam<double> step;    // STEP,s (s > 0)
  FincutParam fincut;          // FINCUT
  ThreadParam<int> option;     // OPTION,0..4
  ThreadParam<double> cutang;  // CUTANG,-360..360
  ThreadParam<double> tlangl;  // TLANGL, 0 < a < 180
  AtanglParam atangl;          // ATANGL,-80..80[,h >= 0]
  ChamfrParam chamfr;          // CHAMFR,L[,10..80]
  ReturnParam ret;             // RETURN[,h > 0]
  ThreadParam<bool> chain;     // CHAIN: the GOTOs are a contour (threading.md section 11)
  PitchWords pitch;            // TPI / IPR / MMPR / PERREV, MULTRD, INCR / DECR
};

// The words parse_thread_words accepts, as listed in its "unknown word" error.
inline constexpr std::string_view kThreadWordList =
    "DEPTH, CUTS, STEP, FINCUT, OPTION, CUTANG, TLANGL, ATANGL, CHAMFR, RETURN, CHAIN, TPI, IPR, "
    "MMPR, PERREV, MULTRD, INCR, DECR";
// The words parse_pitch_words accepts.
inline constexpr std::string_view kPitchWordList = "TPI, IPR, MMPR, PERREV, MULTRD, INCR, DECR";

// Most starts (MULTRD) a thread may have; keeps a plan's size bounded on hostile input.
inline constexpr int kMaxStarts = 100;
// Most passes (roughing + finish) of one thread.
inline constexpr int kMaxPasses = 200;

// Parses THREAD/ON parameters from `st.args[first_arg]` on (after ON, or after THREAD,TURN in the
// Pro/E OP form), in any order. Reports every error found (at the offending word) and returns
// false if there was one.
bool parse_thread_words(const Statement& st, size_t first_arg, LengthUnit cl_units,
                        ThreadWords& out, Diagnostics& diags);

// Parses pitch words from `st.args[first_arg]` on:
//   PITCH/v[,TPI|IPR|MMPR|PERREV][,MULTRD,n][,INCR|DECR,dv]   (a leading value, then qualifiers)
//   COUPLE/ON,TPI,v | IPR,v | MMPR,v | PERREV,v [,MULTRD,n][,INCR|DECR,dv]   (couplets)
// and updates the parts of `pitch` that were given (for PITCH/ pass a default PitchSpec so the
// statement replaces the modal state; for COUPLE/ON and THREAD/kind pass a copy of the modal
// state). A PITCH/ statement must give a value. An unqualified value v means v threads per CL
// unit. dv is in CL units per revolution. Returns false (with diagnostics) on any error; `pitch`
// is then unchanged.
bool parse_pitch_words(const Statement& st, size_t first_arg, LengthUnit cl_units, PitchSpec& pitch,
                       Diagnostics& diags);

}  // namespace clpost
