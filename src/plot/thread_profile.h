#pragma once
// The geometry behind the section picture: where each pass's V sits and what the part looks like
// after all of them. Section coordinates: u along the cutting direction (the thread axis for a
// turned thread), d the depth below the thread surface (d > 0 is into the part), both in the
// section's units.
#include <vector>

#include "simulator/toolpath.h"

namespace clpost {

struct SectionPoint {
  double u = 0;
  double d = 0;
};

// tan of half the tool's included angle (the angle clamped to 1..179 degrees; 60 when not
// finite).
double half_angle_tan(const ThreadSection& s);

// The pitch used to place the grooves: `pitch` when positive, else lead / starts, else 1.5 times
// the width of the V at depth D (1 when that is zero too).
double groove_pitch(const ThreadSection& s);

// How many grooves the picture shows: the starts (at least 1, at most 24) or more when a pass
// names a higher start index.
int groove_count(const ThreadSection& s);

// Whether a pass has finite depth and shift (only those are drawn).
bool drawable(const SectionPass& p);

// The tip of a pass's V: u = start x groove_pitch + shift, d = depth.
SectionPoint pass_tip(const ThreadSection& s, const SectionPass& p);

// The V tips that cut the part: every drawable pass, or when there is none, one V of depth D
// (0 when not finite) per groove at zero shift (the nominal form).
std::vector<SectionPoint> cutting_tips(const ThreadSection& s);

// The part's surface after every cut, over [u_lo, u_hi], left to right: depth
// max(0, V depths at u), with each tip repeated one lead (groove_count x groove_pitch) to either
// side so the grooves at the edges are drawn too. Exact at the tips and where the Vs leave the
// surface, sampled at `samples` points in between (straight flanks look straight).
std::vector<SectionPoint> cut_profile(const ThreadSection& s, double u_lo, double u_hi,
                                      int samples = 600);

}  // namespace clpost
