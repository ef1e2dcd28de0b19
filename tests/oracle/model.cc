// The model, statement by statement: each handler is one row (or a few) of docs/cl-meaning.md.
#include "model.h"

#include <cmath>

#include "model_impl.h"

namespace oracle::detail {

bool Model::fail(const ClStatement& st, const std::string& why) {
  error_ = "CL line " + std::to_string(st.line) + ": " + why + " (" + st.text + ")";
  return false;
}

void Model::push(Event e, const ClStatement& st) {
  e.state = m_;
  if (!m_.spindle.css) e.state.spindle.limit = 0;
  const bool modal_pitch = e.why.modal_pitch;
  e.why = why_;
  e.why.modal_pitch = modal_pitch;
  e.skipped = in_range_;
  e.inch = inch_;
  e.line = st.line;
  e.source = st.text;
  if (!in_range_ && range_closed_ && e.kind == Event::Kind::kMotion) {
    e.why.after_range = true;
    range_closed_ = false;
  }
  events_.push_back(e);
}

bool Model::statement(const ClStatement& st) {
  const std::string& w = st.major;
  if (w == "FINI") return false;
  if (w == "PARTNO" || w == "PPRINT" || w == "END") return true;  // INSERT: verbatim NC, unknown
  if (w == "GOTO" || w == "GODLTA" || w == "FROM" || w == "GOHOME" || w == "CIRCLE" || w == "RAPID")
    return dispatch_motion(st);
  return dispatch_state(st);
}

bool Model::dispatch_motion(const ClStatement& st) {
  const std::string& w = st.major;
  if (w == "GOTO") return go_to(st);
  if (w == "GODLTA") return godlta(st);
  if (w == "FROM") return from(st);
  if (w == "GOHOME") return gohome(st);
  if (w == "CIRCLE") return circle(st);
  rapid_next_ = true;  // RAPID: exactly the next motion
  return true;
}

bool Model::dispatch_state(const ClStatement& st) {
  const std::string& w = st.major;
  if (w == "UNITS" || w == "UNIT") return units(st);
  if (w == "FEDRAT") return fedrat(st);
  if (w == "SPINDL") return spindl(st);
  if (w == "LOADTL" || w == "TURRET") return loadtl(st, 0);
  if (w == "LOAD" && st.find("TOOL") == 0) return loadtl(st, 1);
  if (w == "DELAY") return delay(st);
  if (w == "PITCH") return pitch(st);
  if (w == "THREAD") return thread(st);
  if (w == "COUPLE") return couple(st);
  if (w == "COOLNT") return coolnt(st);
  if (w == "OPSKIP") return opskip(st);
  return fail(st, "the model does not know " + w);
}

bool Model::units(const ClStatement& st) {
  bool inch;
  if (st.has("MM") || st.has("MILLIMETERS") || st.has("METRIC"))
    inch = false;
  else if (st.has("INCHES") || st.has("INCH") || st.has("IN"))
    inch = true;
  else
    return fail(st, "UNITS/ needs MM or INCHES");
  if (inch != inch_) {
    why_.units_since_feed = true;
    why_.units_since_spindle = true;
    why_.units_since_pitch = true;
  }
  inch_ = inch;
  return true;
}

// A straight move or an arc to (x, z) mm, as the statements before it say.
bool Model::move(const ClStatement& st, double x, double z, bool may_be_arc) {
  Event e;
  e.x = x, e.z = z;
  if (thread_gotos_ == 1 || coupled_) {
    if (coupled_ && (circle_ || rapid_next_)) return fail(st, "COUPLE/ cuts straight moves only");
    e.motion = MotionKind::kThread;
    e.lead = thread_lead_;
    e.why.modal_pitch = thread_modal_pitch_;
    if (!coupled_) thread_gotos_ = -1;
  } else if (circle_) {
    if (!may_be_arc) return fail(st, "CIRCLE/ applies to a GOTO");
    if (!have_pos_) return fail(st, "an arc needs a start point");
    e.motion = MotionKind::kArc;
    e.cx = circle_->cx, e.cz = circle_->cz, e.rotation = circle_->rotation;
    circle_.reset();
  } else {
    e.motion = rapid_next_ ? MotionKind::kRapid : MotionKind::kFeed;
    if (thread_gotos_ == 0) thread_gotos_ = 1;
  }
  if (e.motion != MotionKind::kRapid && e.motion != MotionKind::kThread && !m_.feed_given)
    return fail(st, "a feed move before any FEDRAT/");
  rapid_next_ = false;
  have_pos_ = true;
  x_ = x, z_ = z;
  push(e, st);
  return true;
}

bool Model::go_to(const ClStatement& st) {
  if (st.args.size() < 2 || !st.is_number(0) || !st.is_number(1))
    return fail(st, "GOTO/ needs x,y[,z]");
  const double z = st.args.size() >= 3 ? len(st.number(2)) : z_;
  return move(st, len(st.number(0)), z, true);
}

bool Model::godlta(const ClStatement& st) {
  if (!have_pos_) return fail(st, "GODLTA/ needs a position");
  if (st.args.size() == 1) return move(st, x_, z_ + len(st.number(0)), false);
  const double dz = st.args.size() >= 3 ? len(st.number(2)) : 0;
  return move(st, x_ + len(st.number(0)), z_ + dz, false);
}

bool Model::from(const ClStatement& st) {
  if (st.args.size() < 3) return fail(st, "FROM/ needs x,y,z");
  have_pos_ = true;
  x_ = len(st.number(0)), z_ = len(st.number(2));
  return true;
}

bool Model::gohome(const ClStatement& st) {
  if (st.args.size() < 3) return fail(st, "GOHOME without a point goes to the machine's home");
  Event e;
  e.motion = MotionKind::kRapid;
  e.x = len(st.number(0)), e.z = len(st.number(2));
  e.home = opts_.home_is_reference ? kHomeX | kHomeZ : 0;  // GOHOME: every axis
  rapid_next_ = false;  // GOHOME is the motion a pending RAPID applies to
  have_pos_ = true;
  x_ = e.x, z_ = e.z;
  push(e, st);
  return true;
}

bool Model::circle(const ClStatement& st) {
  if (st.args.size() < 7) return fail(st, "CIRCLE/ needs cx,cy,cz,i,j,k,r");
  const double i = st.number(3), j = st.number(4), k = st.number(5);
  if (std::abs(i) > 1e-9 || std::abs(k) > 1e-9 || std::abs(j) < 1e-9)
    return fail(st, "an arc in the turning plane has its axis along Y");
  // Right-hand rule: axis +Y turns +Z toward +X, counter-clockwise in (Z, X) seen from +Y.
  circle_ = Arc{len(st.number(0)), len(st.number(2)), j > 0 ? 1 : -1};
  return true;
}

}  // namespace oracle::detail

namespace oracle {

ModelResult model_events(std::string_view cl, const ModelOptions& opts) {
  detail::Model model(opts);
  for (const ClStatement& st : read_cl(cl))
    if (!model.statement(st)) break;
  return model.result();
}

}  // namespace oracle
