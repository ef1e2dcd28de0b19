// The lathe frame (post_state.h): which CL axis carries the radius. With cl.radial_axis: auto
// the first point off the spindle axis decides it; a program that then moves along the third
// axis is an error, never a program silently cut with X0.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/post_state.h"

namespace clpost {

namespace {

constexpr double kOffPlane = 1e-6;  // CL units: a coordinate this small is 0

char axis_name(ClAxis a) {
  return "XYZ"[static_cast<int>(a)];
}

// The two axes besides the axial one, in X, Y, Z order.
std::pair<ClAxis, ClAxis> plane_axes(const Machine& m) {
  const int axial = static_cast<int>(m.cl_axial);
  const int a = axial == 0 ? 1 : 0, b = axial == 2 ? 1 : 2;
  return {static_cast<ClAxis>(a), static_cast<ClAxis>(b)};
}

bool decide(PostState& s, const Statement& st, Point3 p) {
  const auto [a, b] = plane_axes(s.m);
  const double va = axis_value(p, a), vb = axis_value(p, b);
  const bool on_a = std::abs(va) > kOffPlane, on_b = std::abs(vb) > kOffPlane;
  if (!on_a && !on_b) return true;
  if (on_a && on_b) {
    error(s, st, st.loc,
          fmt::format("CL {} = {} and {} = {}: the point is off the lathe plane, so neither can "
                      "be the radius (cl.radial_axis: auto); is this a milling program? Set "
                      "cl.radial_axis to post it anyway",
                      axis_name(a), va, axis_name(b), vb));
    return false;
  }
  s.radial = on_a ? a : b;
  s.radial_found = st.loc.line;
  s.off_plane_axis = static_cast<int>(third_axis(s));
  // The usual frame (the first candidate, X when Z is the axis) goes without a note: the
  // program is the one a fixed `radial_axis: x` gives.
  if (s.radial != a)
    note_once(s, st, "radial-axis",
              fmt::format("the radius is CL {} and CL {} is 0 (cl.radial_axis: auto, found here)",
                          axis_name(s.radial), axis_name(a)));
  return true;
}

}  // namespace

void frame_normal(PostState& s, const Statement& st, Point3 n) {
  if (!s.radial_auto || s.radial_found != 0) return;
  const auto [a, b] = plane_axes(s.m);
  const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  if (!(len > 0)) return;
  for (const ClAxis normal : {a, b}) {
    if (std::abs(std::abs(axis_value(n, normal)) / len - 1) > 1e-6) continue;
    s.radial = normal == a ? b : a;
    s.radial_found = st.loc.line;
    s.off_plane_axis = static_cast<int>(third_axis(s));
    if (s.radial != a)
      note_once(s, st, "radial-axis",
                fmt::format("the radius is CL {}: the arc turns about CL {} (cl.radial_axis: auto, "
                            "found here)",
                            axis_name(s.radial), axis_name(normal)));
    return;
  }
}

bool frame_point_checked(PostState& s, const Statement& st, const Point3& p) {
  if (s.radial_auto && s.radial_found == 0) return decide(s, st, p);
  const ClAxis third = third_axis(s);
  const double off = axis_value(p, third);
  if (!(std::abs(off) > kOffPlane)) return true;
  if (s.radial_auto) {
    error(s, st, st.loc,
          fmt::format("CL {} = {} but the radius is CL {} (found at line {}): the program moves "
                      "in both, off the lathe plane (is this a milling program? set "
                      "cl.radial_axis to post it anyway)",
                      axis_name(third), off, axis_name(s.radial), s.radial_found));
    return false;
  }
  if (s.y_warnings++ == 0) {
    warning(s, st, st.loc,
            fmt::format("{} = {} but a lathe has no such axis: ignored (the first of such points; "
                        "is this a milling program?)",
                        axis_name(third), off));
  }
  return true;
}

}  // namespace clpost
