// The model's modal statements: FEDRAT, SPINDL, LOADTL, DELAY, PITCH, THREAD, COOLNT, OPSKIP
// (docs/cl-meaning.md, one row or a few each).
#include <cmath>

#include "model_impl.h"

namespace oracle::detail {

namespace {

constexpr double kMPerFoot = 0.3048;

}  // namespace

bool Model::fedrat(const ClStatement& st) {
  const int at = st.first_number();
  if (at < 0 || !(st.number(at) > 0)) return fail(st, "FEDRAT/ needs a positive feed");
  double value = len(st.number(at));  // no mode word: CL units, the current mode
  FeedMode mode = m_.feed_mode;
  bool with_mode = true;
  if (st.has("MMPM") || st.has("MMPR")) {
    value = st.number(at), mode = st.has("MMPM") ? FeedMode::kPerMinute : FeedMode::kPerRev;
  } else if (st.has("IPM") || st.has("IPR")) {
    value = st.number(at) * kMmPerInch;
    mode = st.has("IPM") ? FeedMode::kPerMinute : FeedMode::kPerRev;
  } else if (st.has("PERMIN") || st.has("PERREV")) {
    mode = st.has("PERMIN") ? FeedMode::kPerMinute : FeedMode::kPerRev;
  } else {
    with_mode = false;
  }
  m_.feed = value, m_.feed_mode = mode, m_.feed_given = true;
  why_.feed_line = st.line;
  why_.feed_without_mode = !with_mode;
  why_.units_since_feed = false;
  why_.feed_in_range = in_range_;
  return true;
}

bool Model::spindl(const ClStatement& st) {
  Spindle& sp = m_.spindle;
  if (st.has("CLW")) sp.dir = SpindleDir::kCw;
  if (st.has("CCLW")) sp.dir = SpindleDir::kCcw;
  const int max_at = st.find("MAXRPM");
  if (max_at >= 0) {
    if (!st.is_number(max_at + 1)) return fail(st, "MAXRPM needs a limit");
    spindle_limit_ = st.number(max_at + 1);
  }
  why_.spindle_line = st.line;
  why_.spindle_by_on = false;
  why_.maxrpm_from_earlier = max_at < 0 && maxrpm_given_;
  why_.tool_change_since_spindle = false;
  why_.spindle_in_range = in_range_;
  maxrpm_given_ = maxrpm_given_ || max_at >= 0;
  int value_at = -1;
  for (size_t i = 0; i < st.args.size(); ++i)
    if (st.is_number(i) && (max_at < 0 || static_cast<int>(i) != max_at + 1))
      value_at = static_cast<int>(i);
  if (st.has("OFF")) {
    sp.on = false;
    return true;
  }
  if (value_at < 0) {  // SPINDL/ON: as last given
    if (!st.has("ON") || !speed_given_) return fail(st, "SPINDL/ needs a speed");
    why_.spindle_by_on = true;
    sp.on = true;
    sp.limit = spindle_limit_;
    return true;
  }
  return spindle_speed(st, value_at);
}

// SPINDL/ with a speed: RPM unless SMM or SFM; it turns the spindle on.
bool Model::spindle_speed(const ClStatement& st, int value_at) {
  Spindle& sp = m_.spindle;
  const double v = st.number(value_at);
  if (!(v > 0)) return fail(st, "a spindle speed is positive");
  sp.css = st.has("SMM") || st.has("SFM");
  sp.speed = st.has("SFM") ? v * kMPerFoot : v;
  sp.limit = spindle_limit_;
  sp.on = true;
  speed_given_ = true;
  why_.units_since_spindle = false;  // (OFF and ON keep the speed of before)
  return true;
}

bool Model::loadtl(const ClStatement& st, size_t first) {
  if (!st.is_number(first)) return fail(st, "a tool change needs a tool number");
  m_.tool = static_cast<int>(st.number(first));
  m_.offset = m_.tool;
  for (const char* word : {"ADJUST", "OSETNO", "OFFSET"}) {
    const int at = st.find(word);
    if (at >= 0 && st.is_number(at + 1)) m_.offset = static_cast<int>(st.number(at + 1));
  }
  why_.tool_line = st.line;
  why_.tool_change_since_spindle = true;
  return true;
}

bool Model::delay(const ClStatement& st) {
  const int at = st.first_number();
  if (at < 0 || st.number(at) < 0) return fail(st, "DELAY/ needs a time or a number of turns");
  Event e;
  e.kind = Event::Kind::kDwell;
  e.seconds = st.number(at);
  if (st.has("REV")) {
    const Spindle& sp = m_.spindle;
    if (!sp.on || sp.css || !(sp.speed > 0))
      return fail(st, "a dwell in revolutions needs the spindle turning at a set RPM");
    e.seconds = st.number(at) * 60 / sp.speed;
  }
  push(e, st);
  return true;
}

// The pitch the words of `st` give (PITCH/, COUPLE/ON), in mm.
bool Model::pitch_of(const ClStatement& st, double& mm) {
  const int at = st.first_number();
  if (at < 0 || !(st.number(at) > 0)) return fail(st, "a pitch needs a positive value");
  const double v = st.number(at);
  if (st.has("MMPR"))
    mm = v;
  else if (st.has("IPR"))
    mm = v * kMmPerInch;
  else if (st.has("PERREV"))
    mm = len(v);
  else if (st.has("TPI"))
    mm = kMmPerInch / v;
  else
    mm = len(1 / v);  // threads per CL unit
  return true;
}

bool Model::pitch(const ClStatement& st) {
  if (!pitch_of(st, pitch_)) return false;
  why_.units_since_pitch = false;
  return true;
}

// COUPLE/ON[,pitch words] … COUPLE/OFF: every GOTO in between one thread cut from where the tool
// is, at the pitch of its own words (this thread only) or the modal one, in a row (threading.md
// §1, §10).
bool Model::couple(const ClStatement& st) {
  if (st.has("OFF")) {
    coupled_ = false;
    return true;
  }
  if (!st.has("ON")) return fail(st, "COUPLE/ needs ON or OFF");
  thread_modal_pitch_ = st.first_number() < 0;
  thread_lead_ = pitch_;
  if (!thread_modal_pitch_ && !pitch_of(st, thread_lead_)) return false;
  if (!(thread_lead_ > 0)) return fail(st, "a thread needs a pitch");
  coupled_ = true;
  return true;
}

bool Model::thread(const ClStatement& st) {
  if (!(st.has("TURN") || st.has("FACE") || st.has("TAPER")))
    return fail(st, "the model knows the single-pass THREAD/TURN|FACE|TAPER only");
  const int at = st.first_number();
  thread_lead_ = at >= 0 ? len(st.number(at)) : pitch_;
  thread_modal_pitch_ = at < 0;
  if (!(thread_lead_ > 0)) return fail(st, "a thread needs a pitch");
  thread_gotos_ = 0;
  return true;
}

bool Model::coolnt(const ClStatement& st) {
  Coolant& c = m_.coolant;
  if (st.has("ON") || st.has("FLOOD"))
    c = Coolant{true, false};
  else if (st.has("MIST"))
    c = Coolant{false, true};
  else if (st.has("OFF"))
    c = Coolant{};
  else
    return fail(st, "COOLNT/ needs ON, FLOOD, MIST or OFF");
  why_.coolant_in_range = in_range_;
  return true;
}

bool Model::opskip(const ClStatement& st) {
  if (st.has("ON")) {
    in_range_ = true;
  } else if (st.has("OFF")) {
    if (in_range_) range_closed_ = true;
    in_range_ = false;
  } else {
    return fail(st, "OPSKIP/ needs ON or OFF");
  }
  return true;
}

}  // namespace oracle::detail
