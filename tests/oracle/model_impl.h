#pragma once
// The model's state and its statement handlers (model.cc: motion, model_state.cc: feed, spindle,
// tools, dwells, threads, coolant, OPSKIP). Internal to the oracle; model.h is the interface.
#include <optional>
#include <string>
#include <vector>

#include "cl_text.h"
#include "model.h"

namespace oracle::detail {

class Model {
 public:
  explicit Model(const ModelOptions& o) : opts_(o), inch_(o.inch) { spindle_limit_ = o.max_rpm; }
  // False after FINI or an error.
  bool statement(const ClStatement& st);
  ModelResult result() { return {std::move(events_), std::move(error_)}; }

 private:
  double len(double v) const { return inch_ ? v * kMmPerInch : v; }
  bool fail(const ClStatement& st, const std::string& why);
  bool dispatch_motion(const ClStatement& st);
  bool dispatch_state(const ClStatement& st);
  bool units(const ClStatement& st);
  bool go_to(const ClStatement& st);
  bool godlta(const ClStatement& st);
  bool from(const ClStatement& st);
  bool gohome(const ClStatement& st);
  bool circle(const ClStatement& st);
  bool move(const ClStatement& st, double x, double z, bool may_be_arc);
  bool fedrat(const ClStatement& st);
  bool spindl(const ClStatement& st);
  bool spindle_speed(const ClStatement& st, int value_at);
  bool loadtl(const ClStatement& st, size_t first);
  bool delay(const ClStatement& st);
  bool pitch(const ClStatement& st);
  bool pitch_of(const ClStatement& st, double& mm);
  bool thread(const ClStatement& st);
  bool couple(const ClStatement& st);
  bool coolnt(const ClStatement& st);
  bool opskip(const ClStatement& st);
  void push(Event e, const ClStatement& st);

  ModelOptions opts_;
  bool inch_;
  bool have_pos_ = false;
  double x_ = 0, z_ = 0;
  bool rapid_next_ = false;
  struct Arc {
    double cx, cz;
    int rotation;
  };
  std::optional<Arc> circle_;
  Modal m_;
  Provenance why_;
  bool speed_given_ = false;
  double spindle_limit_ = 0;
  bool maxrpm_given_ = false;
  double pitch_ = 0;        // mm/rev
  int thread_gotos_ = -1;   // a THREAD/TURN's GOTOs seen so far; -1: none pending
  double thread_lead_ = 0;  // mm/rev
  bool thread_modal_pitch_ = false;
  bool coupled_ = false;  // between COUPLE/ON and COUPLE/OFF: every GOTO a thread cut
  bool in_range_ = false;
  bool range_closed_ = false;
  std::vector<Event> events_;
  std::string error_;
};

}  // namespace oracle::detail
