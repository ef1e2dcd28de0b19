#pragma once
// The turning path (turning_path.cc, tool_path.h): the main spindle turns the part and the tool
// moves in the lathe plane, as the frame maps the CL's points (frame.cc). Its moves are the
// lathe's (move_to), its holes on the centre line (hole_goto.cc), its threads the thread
// sequences' (thread_statements.cc). No state of its own: the main spindle and the lathe frame
// are every path's.
#include "interpreter/tool_path.h"

namespace clpost {

class TurningPath final : public ToolPath {
 public:
  void prepare(PostState&, const Statement&) override {}
  void begin(PostState&, const Statement&) override {}
  void leave(PostState& s, const Statement& st, bool program_end) override;
  void tool_axis(PostState& s, const Statement& st) override;
  void go_to(PostState& s, const Statement& st, const Point3& p) override;
  void go_delta(PostState& s, const Statement& st, const Point3& p) override;
  void circle(PostState& s, const Statement& st, const Circle& c) override;
  void helical(PostState& s, const Statement& st) override;
  void go(PostState& s, const Statement& st) override;
  void part_surface(PostState& s, const Statement& st) override;
  void rapid_reached(double) override {}
  void spindle(PostState& s, const Statement& st, SpindleWords w) override;
  bool turns_main_spindle() const override { return true; }
  void cutter_comp(PostState& s, const Statement& st, const Arg& word, CutterComp c) override;
  void before_c_index(PostState&, const Statement&) override {}
};

}  // namespace clpost
