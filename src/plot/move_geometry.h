#pragma once
// Geometry of toolpath moves for drawing: arc sweeps and the box a program's moves cover. The
// frame is the CL lathe frame (simulator/toolpath.h); arcs are read with Z to the right and X up
// (G18 seen from +Y), where kArcCw (G2) turns clockwise.
#include <array>
#include <cstddef>
#include <vector>

#include "simulator/toolpath.h"

namespace clpost {

// Whether every coordinate a move uses (from, to, and center for arcs) is finite.
bool finite_move(const Move& m);

struct ArcSweep {
  double radius = 0;  // mean of the center's distances to from and to
  double start = 0;   // angle of `from` around the center, radians, from +Z toward +X
  double sweep = 0;   // signed: > 0 counterclockwise, < 0 clockwise; a full turn when from == to
};

// The sweep of an arc move (kArcCw or kArcCcw); radius 0 when from or to sits on the center.
ArcSweep arc_sweep(const Move& m);

// The point at `angle` on a circle of `radius` around `center`.
Vec2 arc_point(Vec2 center, double radius, double angle);

struct Bounds {
  bool empty = true;
  double z_lo = 0, z_hi = 0, x_lo = 0, x_hi = 0;
  void add(Vec2 p);
};

// The drawing class of a move (backplot_svg.h): 0 rapid, 1 feed, 2 arc (either way), 3 thread.
size_t draw_class(MoveKind k);

// The move's end points, and for an arc its extreme points (where it crosses the directions +-Z
// and +-X from its center), added to `b`.
void add_move_bounds(Bounds& b, const Move& m);

// What a whole path measures, gathered move by move as the moves stream past (a picture that
// draws fewer moves still counts and measures them all): finite moves only.
struct PathMeasure {
  std::array<size_t, 4> moves{};   // by draw_class
  std::array<double, 4> length{};  // along the move (arcs: along the arc), program units
  Bounds all;                      // every move
  Bounds cut;                      // the moves that cut (feeds, arcs, threads)
  bool has_start = false;          // the first move's start
  Vec2 start;
  void add(const Move& m);
  size_t total() const { return moves[0] + moves[1] + moves[2] + moves[3]; }
};

// The box covering every finite move's end points, and for arcs their extreme points (where the
// arc crosses the directions +-Z and +-X from its center). Without `rapids`, only the moves that
// cut (feeds, arcs, threads).
Bounds toolpath_bounds(const Toolpath& tp, bool rapids = true);

}  // namespace clpost
