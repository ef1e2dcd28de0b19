// A radial live tool on a machine without Y (docs/millturn.md, "Peripheral milling without Y"): C
// turns the part so that the tool axis stands on the machine's X axis, so every point the tool
// reaches lies on the line of its axis through the centre line.
#include <fmt/format.h>

#include <cmath>

#include "interpreter/milling_parts.h"

namespace clpost {

namespace {

// How far the radial tool's tip `p` is off the line of the tool axis through the centre line
// (`off`), and how far along the axis from the centre line it stands (`along`), in CL units.
struct ToolLine {
  double off = 0, along = 0;
};

ToolLine tool_line(Point3 axis, Point3 p) {
  return {std::abs(p.x * axis.y - p.y * axis.x), p.x * axis.x + p.y * axis.y};
}

// A radial tool's tip on a machine without Y (docs/millturn.md, "Peripheral milling without
// Y"): C turns the part so that the tool axis stands on the machine's X axis, so the tip must lie
// on the line of its axis through the centre line (within millturn.xzc_tolerance), on the tool's
// side of it. False (reported) otherwise: the offset needs Y.
bool on_tool_line(PostState& s, LiveState& l, const Statement& st, Point3 p,
                  const std::string& what) {
  const ToolLine t = tool_line(s.tool_axis.dir, p);
  const Point3 a = s.tool_axis.dir;
  if (t.off > s.m.xzc_tolerance) {
    refuse_milling(
        s, l, st,
        fmt::format("{} is {:.4f} mm off the line of the tool axis ({:g}, {:g}, {:g}) through "
                    "the centre line (millturn.xzc_tolerance {:g}): a radial tool reaches it "
                    "with a Y axis only, and machine '{}' has none",
                    what, t.off, a.x, a.y, a.z, s.m.xzc_tolerance, s.m.name));
    return false;
  }
  if (t.along <= s.m.xzc_tolerance) {
    refuse_milling(
        s, l, st,
        fmt::format("{} is {:.4f} mm from the centre line along the tool axis ({:g}, {:g}, "
                    "{:g}): a radial tool's tip at or past the centre line is not written",
                    what, t.along, a.x, a.y, a.z));
    return false;
  }
  return true;
}

}  // namespace

Point3 machine_tip(const PostState& s, const MotionStart& ms, Point3 p) {
  if (!ms.radial || s.m.y_axis) return p;
  const double r = std::hypot(p.x, p.y), a = std::hypot(s.tool_axis.dir.x, s.tool_axis.dir.y);
  return {r * s.tool_axis.dir.x / a, r * s.tool_axis.dir.y / a, p.z};
}

bool tip_reached(PostState& s, LiveState& l, const Statement& st, const MotionStart& ms, Point3 p) {
  if (!ms.radial || s.m.y_axis) return true;
  return on_tool_line(s, l, st, p, fmt::format("the tip ({:g}, {:g}, {:g})", p.x, p.y, p.z));
}

bool xzc_arc_reached(PostState& s, LiveState& l, const Statement& st, const MillArc& c,
                     const std::vector<Point3>& points, bool radial) {
  if (std::abs(std::abs(c.axis.z) - 1) <= 1e-6) return true;
  if (!radial) {
    refuse_milling(s, l, st, "an arc about another axis than the spindle's needs a Y axis");
    return false;
  }
  Point3 far = points.front(), near = points.front();
  for (const Point3& p : points) {
    if (tool_line(s.tool_axis.dir, p).off > tool_line(s.tool_axis.dir, far).off) far = p;
    if (tool_line(s.tool_axis.dir, p).along < tool_line(s.tool_axis.dir, near).along) near = p;
  }
  const Point3 worst = tool_line(s.tool_axis.dir, far).off > s.m.xzc_tolerance ? far : near;
  return on_tool_line(s, l, st, worst,
                      fmt::format("the arc of line {} about ({:g}, {:g}, {:g}) at ({:.5g}, {:.5g}, "
                                  "{:.5g})",
                                  c.line, c.axis.x, c.axis.y, c.axis.z, worst.x, worst.y, worst.z));
}

}  // namespace clpost
