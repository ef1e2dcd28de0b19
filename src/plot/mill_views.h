#pragma once
// The C-axis work of a live tool gathered for the backplot's face and peripheral views
// (docs/millturn.md, "verify and plot"), as the program's moves stream past, in memory bounded
// like the side view's (path_thinner.h):
//  - the face view looks at the part face along -Z, in the part frame at C0: a machine position
//    X (a radius), Y, C is the point laws/xzc_law.h part_of_machine gives (X turned by C), drawn
//    with part X to the right and part Y up, so C0 points right;
//  - the unrolled peripheral view has Z to the right and the arc length R * angle up, the angle
//    the part point's about Z from C0; R, the radius it is unrolled at, is the first peripheral
//    feed's start (the rapids before it are not drawn), else the stock's (the largest turned
//    radius), else the first radial hole's top (its R plane).
// A move of the machine's X, Y, Z or C is C work while the tool that last wrote C (or last moved
// in G17 or G19 once C was written) is loaded; it goes to the peripheral view in G19 (the side
// plane, a radial tool: without Y its X Z C moves when the machine writes plane_side, as
// linuxcnc-lathe-c does), and on a machine with Y in G18 too (haas-st-20y's radial tool moves
// X Y Z there), else to the face view (G17, and XZC work without a plane code:
// fanuc-0i-tf-live's radial milling is drawn there). A
// move that turns C is drawn in steps of at most 5 degrees, so a C index at a radius shows as the
// arc the tool describes on the part; a G2/G3 is drawn along its arc in its plane (G17, G18,
// G19, centre words I J K from its start) the same way. Holes: a face hole (drilled along Z) is a
// mark at its X and C, a radial hole (along X) a mark at its Z and C.
#include <cstddef>
#include <vector>

#include "laws/xzc_law.h"
#include "plot/path_thinner.h"
#include "simulator/control_sim.h"

namespace clpost {

// What the views draw. Moves are Move records in the view's plane: Vec2::z across (face: part
// X; peripheral: Z), Vec2::x up (face: part Y; peripheral: R * angle).
struct MillViewsDrawn {
  ThinnedPath face, peripheral;
  std::vector<Vec2> face_holes, radial_holes;  // the marks, in the same coordinates
  size_t holes_not_drawn = 0;                  // past kMaxHoleMarks
  double stock_radius = 0;                     // the circle drawn in the face view (0: none)
  bool stock_turned = false;  // stock_radius is the largest turned radius, else the work's
  double unroll_radius = 0;   // R of the peripheral view
  // A view is drawn when it has work: holes, or moves that are not rapids.
  bool has_face() const { return cuts(face) || !face_holes.empty(); }
  bool has_peripheral() const { return cuts(peripheral) || !radial_holes.empty(); }
  bool any() const { return has_face() || has_peripheral(); }
  static bool cuts(const ThinnedPath& p) { return p.measure.total() > p.measure.moves[0]; }
};

inline constexpr size_t kMaxHoleMarks = 20000;

class MillViews {
 public:
  // `rollover`: the control turns C the shortest way to a C word (millturn.c_rotation);
  // `y_axis`: the machine has Y (millturn.y_axis), whose radial tool mills in G18 too.
  explicit MillViews(bool rollover, bool y_axis = false, ThinOptions options = {});
  // Each move in X, Y, Z, C as the simulation hands it over (SimOptions::on_mill_move).
  void mill_move(const SimMillMove& m);
  // Each move of the side view (SimOptions::on_move): the feeds of other tools turn the stock.
  // Whether the side view draws it: not the C-axis work of the tool that writes C, nor a
  // milling feed (Move::mill), which are not turning and which the face and peripheral views
  // draw.
  bool side_move(const Move& m, const CutState& state);
  // The program's holes (Simulation::holes), at the end; then the views.
  MillViewsDrawn finish(const std::vector<SimHole>& holes, LengthUnit units);

 private:
  void draw(const SimMillMove& from, const SimMillMove& to);
  double unrolled(Point3 p);

  bool rollover_;
  bool y_axis_;
  PathThinner face_, peripheral_;
  bool has_prev_ = false;
  SimMillMove prev_;
  int c_tool_ = -2;         // the tool that last wrote C (-2: none yet)
  bool c_work_ = false;     // the last move was C work
  double last_c_ = 0;       // C of the last move, as written
  bool c_seen_ = false;     // some move had C known
  double stock_ = 0;        // the largest turned radius so far
  double work_radius_ = 0;  // the largest radius of the face work
  double unroll_r_ = 0;     // 0 until the first peripheral work
  bool has_angle_ = false;  // last_angle_ holds the last peripheral point's angle
  double last_angle_ = 0;   // radians, continuous
};

}  // namespace clpost
