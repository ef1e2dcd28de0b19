// DIN 76-1 thread undercuts: the table and the contour (din76_undercut.h).
#include "laws/din76_undercut.h"
#include "support/angles.h"

#include <array>
#include <cmath>
#include <numbers>

namespace clpost {

namespace {

// ISO metric coarse pitches (ISO 261) for CYCLE96's range M3 ... M68. Source for M3 ... M64:
// the coarse "M<d>-<P>" sizes of gumyr/bd_warehouse src/bd_warehouse/data/hex_head_parameters.csv;
// M68 x 6 is the ISO 261 coarse pitch of 68 (not in that file).
struct CoarsePitch {
  double d, pitch;
};
constexpr std::array<CoarsePitch, 26> kCoarse = {
    {{3, 0.5},  {4, 0.7},  {5, 0.8},  {6, 1},  {8, 1.25}, {10, 1.5}, {12, 1.75}, {14, 2}, {16, 2},
     {18, 2.5}, {20, 2.5}, {22, 2.5}, {24, 3}, {27, 3},   {30, 3.5}, {33, 3.5},  {36, 4}, {39, 4},
     {42, 4.5}, {45, 4.5}, {48, 5},   {52, 5}, {56, 5.5}, {60, 5.5}, {64, 6},    {68, 6}}};

// DIN 76-1 thread undercuts for the coarse pitches above, as tabulated ("Undercut DIN 76,
// Parameters") in the HEIDENHAIN CNC PILOT 4290 User's Manual, section 11.1.1, manual page 426
// (https://www.manualsdir.com/manuals/798327/heidenhain-cnc-pilot-4290.html?page=438), columns
// Thr.pitch, I, K, R, W = 30 degrees, "in accordance with DIN 13 for metric threads"; internal
// rows from 1 mm up from the HEIDENHAIN CNC PILOT 640 Operation Manual, section 9.2 "Undercut
// parameters", page 616, which repeats the rows up to 0.8. I is the diameter step (external: the
// undercut diameter is d - I; internal: d + I, its depth measured from the core diameter as
// (N + I - core)/2), K the width, R the radius. The table has one external and one internal
// width per pitch: the normal undercuts, forms A and C. Cross-check (controllers.md, seed 001):
// P = 1.5 form A is depth 1.15 (radius, = I/2), width 5.2, radius 0.8, 30 degrees. The short
// forms B and D are not in the cited table, so clpost does not carry them.
constexpr std::array<Din76Row, 16> kFormA = {{{0.5, 0.8, 1.75, 0.2},
                                              {0.7, 1.1, 2.45, 0.4},
                                              {0.8, 1.3, 2.8, 0.4},
                                              {1, 1.6, 3.5, 0.6},
                                              {1.25, 2, 4.4, 0.6},
                                              {1.5, 2.3, 5.2, 0.8},
                                              {1.75, 2.6, 6.1, 1},
                                              {2, 3, 7, 1},
                                              {2.5, 3.6, 8.7, 1.2},
                                              {3, 4.4, 10.5, 1.6},
                                              {3.5, 5, 12, 1.6},
                                              {4, 5.7, 14, 2},
                                              {4.5, 6.4, 16, 2},
                                              {5, 7, 17.5, 2.5},
                                              {5.5, 7.7, 19, 3.2},
                                              {6, 8.3, 21, 3.2}}};
constexpr std::array<Din76Row, 16> kFormC = {{{0.5, 0.3, 2.7, 0.2},
                                              {0.7, 0.3, 3.8, 0.4},
                                              {0.8, 0.3, 4.2, 0.4},
                                              {1, 0.5, 5.2, 0.6},
                                              {1.25, 0.5, 6.7, 0.6},
                                              {1.5, 0.5, 7.8, 0.8},
                                              {1.75, 0.5, 9.1, 1},
                                              {2, 0.5, 10.3, 1},
                                              {2.5, 0.5, 13, 1.2},
                                              {3, 0.5, 15.2, 1.6},
                                              {3.5, 0.5, 17.7, 1.6},
                                              {4, 0.5, 20, 2},
                                              {4.5, 0.5, 23, 2},
                                              {5, 0.5, 26, 2.5},
                                              {5.5, 0.5, 28, 3.2},
                                              {6, 0.5, 30, 3.2}}};

// The core (minor) diameter of an ISO internal thread: d - 2 x 0.54127 P (controllers.md).
double internal_core(double d, double pitch) {
  return d - 2 * 0.54127 * pitch;
}

}  // namespace

bool internal_form(char form) {
  return form == 'C' || form == 'D';
}

const char* form_name(char form) {
  switch (form) {
    case 'A':
      return "A (external, normal)";
    case 'B':
      return "B (external, short)";
    case 'C':
      return "C (internal, normal)";
    default:
      return "D (internal, short)";
  }
}

std::optional<double> iso_coarse_pitch(double d) {
  for (const CoarsePitch& c : kCoarse)
    if (std::fabs(c.d - d) < 1e-6) return c.pitch;
  return std::nullopt;
}

const Din76Row* din76_row(char form, double pitch) {
  const auto* table = form == 'A' ? &kFormA : form == 'C' ? &kFormC : nullptr;
  if (!table) return nullptr;
  for (const Din76Row& r : *table)
    if (std::fabs(r.pitch - pitch) < 1e-9) return &r;
  return nullptr;
}

UndercutContour din76_contour(double d, double at, char form, int side, const Din76Row& row) {
  const double tan30 = std::tan(radians(30));
  const double s = side < 0 ? -1 : 1;
  UndercutContour c;
  if (!internal_form(form)) {
    const double rt = d / 2, rb = (d - row.diameter_step) / 2, h = rt - rb;
    c.start = {rt + kUndercutClearance, at + s * row.width};
    c.to_fillet = {{rt, at + s * row.width},
                   {rb, at + s * (row.width - h / tan30)},
                   {rb, at + s * row.radius}};
    c.fillet_end = {rb + row.radius, at};
    c.fillet_center = {rb + row.radius, at + s * row.radius};
    c.fillet_ccw = s < 0;
    c.end = {rt + kUndercutClearance, at};
  } else {
    const double rc = internal_core(d, row.pitch) / 2, rb = (d + row.diameter_step) / 2;
    const double h = rb - rc;
    c.start = {rc - kUndercutClearance, at + s * row.width};
    c.to_fillet = {{rc, at + s * row.width},
                   {rb, at + s * (row.width - h / tan30)},
                   {rb, at + s * row.radius}};
    c.fillet_end = {rb - row.radius, at};
    c.fillet_center = {rb - row.radius, at + s * row.radius};
    c.fillet_ccw = s > 0;
    c.end = {rc - kUndercutClearance, at};
  }
  return c;
}

}  // namespace clpost
