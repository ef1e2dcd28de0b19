#pragma once
// DIN 76-1 thread undercuts for ISO metric coarse threads M3 ... M68: the table (diameter step,
// width, radius per pitch, forms A and C) and the undercut's contour. What a control's undercut
// cycle cuts (SINUMERIK CYCLE96, controls/sinumerik/) and what clpost cuts as moves where the
// machine has none (emitters/undercut_output.h).
#include <optional>
#include <vector>

#include "planner/thread_plan.h"

namespace clpost {

// The ISO metric coarse pitch of nominal diameter `d` mm for M3 ... M68 (CYCLE96's range), or
// nothing when `d` is not in that series.
std::optional<double> iso_coarse_pitch(double d);

// One row of the DIN 76-1 undercut table (mm). External forms: the undercut diameter is
// d - diameter_step; internal forms: d + diameter_step. `width` is the undercut's width along
// the axis, `radius` the fillet at the shoulder, the flank toward the thread is at 30 degrees to
// the axis.
struct Din76Row {
  double pitch;
  double diameter_step;
  double width;
  double radius;
};

// The row for `form` ('A'..'D') and `pitch`, or nullptr when clpost does not carry it (only the
// normal forms A and C are cited; see undercut.cc).
const Din76Row* din76_row(char form, double pitch);

// The undercut contour in the CL lathe frame (x a radius, z axial, mm), from the point above the
// thread where it starts to the point beside the shoulder where it ends. The shoulder face is at
// z = `at`; the undercut lies on the side `side` (+1: toward +Z of `at`, -1: toward -Z).
struct UndercutContour {
  Vec2 start;                   // above the flank (external) / inside the bore (internal)
  std::vector<Vec2> to_fillet;  // feed moves: flank top, flank bottom, fillet start
  Vec2 fillet_end, fillet_center;
  bool fillet_ccw = false;  // positive rotation about +Y (G3 in G18)
  Vec2 end;                 // fed up (external) / down (internal) the shoulder face
};
UndercutContour din76_contour(double d, double at, char form, int side, const Din76Row& row);

// Safety clearance of the contour's start and end beyond the thread diameter, mm.
constexpr double kUndercutClearance = 1.0;

// Forms C and D are internal (a bore), A and B external.
bool internal_form(char form);
// "A (external, normal)", ...
const char* form_name(char form);

}  // namespace clpost
