#pragma once
// A program's moves thinned to what a backplot can show, move by move as they stream past, in
// memory bounded by a budget of drawn moves, whatever the program's length.
//
// The rule, at a tolerance of t pixels at the picture's scale (backplot_scale):
//  - rapids keep both ends, and thread (synchronized) moves are kept whole;
//  - a move equal to one already kept (same kind, same ends: identical threads) is drawn once;
//  - joined moves of one drawing class (feeds; arcs short enough to draw straight, whose chord
//    and sagitta are under t) are merged: the end point between two of them is dropped when
//    every point dropped since the last kept one stays within t of the straight line drawn
//    instead, and either the direction turns there by at most kTurnDegrees or the move into it
//    is shorter than t (a move shorter than a pixel is merged whatever its turn);
//  - other arcs are kept whole.
// While the moves stream, the scale is that of what was seen so far, never smaller than the
// final one, so the tolerance in program units only grows; at the end the kept moves are thinned
// once more at the final scale. When more than `budget` moves would be kept, t doubles and the
// kept moves are thinned again (up to kMaxTolerancePx); past that, or when more than half the
// budget are distinct rapids and threads, further moves are counted but not drawn, and
// ThinnedPath::dropped says how many.
#include <cstddef>
#include <string>
#include <unordered_set>
#include <vector>

#include "plot/move_geometry.h"
#include "simulator/toolpath.h"

namespace clpost {

struct ThinOptions {
  double tolerance_px = 0.4;  // t to start with
  size_t budget = 40000;      // moves drawn at most (about 1 MB of SVG path data)
};

inline constexpr double kTurnDegrees = 5;
inline constexpr double kMaxTolerancePx = 12.8;

struct ThinnedPath {
  Toolpath path;        // the moves to draw, in order (units set by finish)
  PathMeasure measure;  // of every move given, drawn or not
  double tolerance_px = 0;
  size_t dropped = 0;  // moves past the budget, not drawn
  // Whether fewer moves are drawn than were given.
  bool simplified() const { return path.moves.size() < measure.total(); }
};

// "path simplified: 1 000 000 moves drawn as 812 (tolerance 0.4 px)", and when moves were left
// out "; 12 345 moves past the budget not drawn"; empty when nothing was simplified.
std::string simplified_note(const ThinnedPath& p);

class PathThinner {
 public:
  explicit PathThinner(ThinOptions options = {});
  void add(const Move& m);
  // The moves given so far (the finite ones: what the picture counts).
  size_t moves() const { return out_.measure.total(); }
  ThinnedPath finish(LengthUnit units);

 private:
  struct Chain {
    bool open = false;
    size_t cls = 0;     // draw_class
    Move tmpl;          // kind, line and state of the merged move
    Vec2 anchor;        // the last kept point
    Vec2 prev;          // the point before `last`
    Vec2 last;          // the end of the pending merged move (not yet kept)
    bool cone = false;  // some dropped point lies farther than t from the anchor
    // Unit directions from the anchor: from lo counterclockwise to hi, the rays pass within t
    // of every dropped point; ref is the first such point's.
    Vec2 ref, lo, hi;
    double far = 0;  // the farthest dropped point from the anchor
  };

  void take(const Move& m, bool fresh);
  void take_straight(const Move& m);
  bool can_drop(Vec2 q, Chain& trial) const;
  void flush();
  void keep(const Move& m);
  void rethin(double scale);
  void note_scale();
  double tol() const;  // t in program units at the current scale

  ThinOptions opt_;
  double tol_px_;
  double scale_ = 0;  // px per unit (0: not known yet)
  ThinnedPath out_;
  Chain chain_;
  struct Key {
    MoveKind kind;
    double fx, fz, tx, tz;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    size_t operator()(const Key& k) const;
  };
  std::unordered_set<Key, KeyHash> seen_;  // the kept moves
  size_t protected_ = 0;                   // rapids and threads kept
  bool full_ = false;                      // past kMaxTolerancePx: nothing more is drawn
};

}  // namespace clpost
