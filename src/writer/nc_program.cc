#include "writer/nc_program.h"

#include <fmt/format.h>

#include <cmath>

#include "writer/number_format.h"

namespace clpost {

namespace {

// Writes template `v.spec()` of machine `m`: every line formatted before any is written.
TemplateWrite write_lines(NcWriter& w, const Machine& m, const TemplateValues& v) {
  TemplateWrite r;
  r.name = v.spec().name;
  auto it = m.templates.find(std::string(r.name));
  if (it == m.templates.end()) {
    r.status = TemplateWrite::Status::kMissing;
    return r;
  }
  std::vector<std::string> lines;
  for (const std::string& line : it->second) {
    TemplateValues::Line l = v.format(line);
    if (!l.missing.empty()) {
      r.status = TemplateWrite::Status::kNoValue;
      r.field = l.missing;
      return r;
    }
    if (!l.ok) {
      r.status = TemplateWrite::Status::kBadLine;
      r.detail = std::move(l.error);
      return r;
    }
    lines.push_back(std::move(l.text));
  }
  for (const std::string& text : lines)
    if (!text.empty()) w.text(text).end_block();
  return r;
}

}  // namespace

std::string template_error(const Machine& m, const TemplateWrite& w) {
  switch (w.status) {
    case TemplateWrite::Status::kMissing:
      return fmt::format(
          "machine '{}' has no template '{}' (templates.{} in its machine or post "
          "file)",
          m.name, w.name, w.name);
    case TemplateWrite::Status::kNoValue:
      return fmt::format("machine '{}': template '{}' needs {{{}}}, which is not known here",
                         m.name, w.name, w.field);
    case TemplateWrite::Status::kBadLine:
      return fmt::format("machine '{}': template '{}' cannot be written: {}", m.name, w.name,
                         w.detail);
    case TemplateWrite::Status::kWritten:
      break;
  }
  return {};
}

NcProgram::NcProgram(const Machine& m, Sink& out)
    : m_(m),
      w_(m, out),
      fmt_x_(m.format_for("X")),
      fmt_z_(m.format_for("Z")),
      fmt_f_(m.format_for("F")),
      fmt_i_(m.format_for("I")),
      fmt_k_(m.format_for("K")),
      code_rapid_(m.code("rapid")),
      code_linear_(m.code("linear")),
      code_arc_cw_(m.code("arc_cw")),
      code_arc_ccw_(m.code("arc_ccw")),
      code_thread_(m.code("thread")) {}

TemplateWrite NcProgram::start(std::string_view program_name, bool inch, std::string_view file) {
  if (units_copy_) use_units(*units_copy_, *units_loaded_, inch);
  TemplateFill<tmpl::kProgramStart> a;
  a.whole<"program_number">(m_.program_number)
      .text<"program_name">(std::string(program_name))
      .text<"units_code">(m_.code(inch ? "inch" : "metric"))
      .text<"machine">(m_.name)
      .text<"file">(std::string(file));
  return write_lines(w_, m_, a);
}

TemplateWrite NcProgram::end(std::string_view program_name) {
  TemplateFill<tmpl::kProgramEnd> a;
  a.whole<"program_number">(m_.program_number).text<"program_name">(std::string(program_name));
  return write_lines(w_, m_, a);
}

TemplateWrite NcProgram::tool_change(int tool, int offset, std::string_view name) {
  TemplateFill<tmpl::kToolChange> a;
  a.whole<"tool">(tool).whole<"offset">(offset).text<"tool_name">(std::string(name));
  TemplateWrite r = write_lines(w_, m_, a);
  forget_modal();
  return r;
}

namespace {
const std::string& direction(const Machine& m, SpindleDir dir) {
  return m.code(dir == SpindleDir::kCw ? "spindle_cw" : "spindle_ccw");
}
}  // namespace

TemplateWrite NcProgram::spindle_rpm(double rpm, SpindleDir dir) {
  TemplateFill<tmpl::kSpindleRpm> a;
  a.text<"rpm">(number_text(rpm, m_.format_for("S"))).text<"direction">(direction(m_, dir));
  // Without a machine limit, the speed itself: no lower limit given before holds it down.
  a.text<"max_rpm">(number_text(m_.max_rpm > 0 ? m_.max_rpm : rpm, m_.format_for("S")));
  TemplateWrite r = write_lines(w_, m_, a);
  if (r) spindle_mode_written(false);
  return r;
}

// On a control whose feed type and spindle mode are one G group (Control::css_feed_per_min):
// the spindle template's code (G96, G97) set feed per revolution, deleting F where the feed type
// was another: the next feed writes its mode (and F) again, with the constant surface speed codes
// while it is on.
void NcProgram::spindle_mode_written(bool css) {
  if (m_.control == nullptr || m_.control->css_feed_per_rev.empty()) return;
  css_on_ = css;
  if (!written_feed_mode_) return;
  if (*written_feed_mode_ != FeedMode::kPerRev) written_feed_.reset();
  written_feed_mode_ = FeedMode::kPerRev;
}

TemplateWrite NcProgram::spindle_css(double speed, double max_rpm, SpindleDir dir) {
  TemplateFill<tmpl::kSpindleCss> a;
  a.text<"speed">(number_text(speed, m_.format_for("S")))
      .text<"max_rpm">(number_text(max_rpm, m_.format_for("S")))
      .text<"direction">(direction(m_, dir));
  TemplateWrite r = write_lines(w_, m_, a);
  if (r) spindle_mode_written(true);
  return r;
}

TemplateWrite NcProgram::spindle_stop() {
  return write_lines(w_, m_, TemplateFill<tmpl::kSpindleStop>());
}

void NcProgram::coolant(Coolant c) {
  static const char* kKeys[] = {"coolant_off", "coolant_flood", "coolant_mist", "coolant_through",
                                "coolant_air"};
  const std::string& code = m_.code(kKeys[static_cast<int>(c)]);
  if (code.empty() && c != Coolant::kOff) {
    w_.comment(
        fmt::format("coolant {} not available on this machine", kKeys[static_cast<int>(c)] + 8));
    return;
  }
  w_.code(code).end_block();
}

void NcProgram::cutter_comp(CutterComp c) {
  static const char* kKeys[] = {"comp_off", "comp_left", "comp_right"};
  w_.code(m_.code(kKeys[static_cast<int>(c)])).end_block();
}

void NcProgram::set_feed(double feed, FeedMode mode) {
  feed_ = feed;
  feed_mode_ = mode;
}

TemplateWrite NcProgram::dwell(std::optional<double> seconds, std::optional<double> revolutions) {
  const NumberFormat& f = m_.format_for("dwell");
  TemplateFill<tmpl::kDwell> a;
  if (seconds) a.text<"seconds">(number_text(*seconds, f));
  if (revolutions) a.text<"revolutions">(number_text(*revolutions, f));
  return write_lines(w_, m_, a);
}

void NcProgram::program_stop(bool optional) {
  w_.code(m_.code(optional ? "optional_stop" : "stop")).end_block();
}

void NcProgram::motion_code(const std::string& c) {
  if (!m_.modal_codes || c != motion_) {
    w_.code(c);
    motion_ = c;
  }
}

namespace {
// `v` as format `f` writes it, taken from `last` when it is the same value (the common case:
// one axis moves, the feed stays).
WrittenNumber written_after(const std::optional<WrittenNumber>& last, double v,
                            const NumberFormat& f) {
  return last && last->value == v ? *last : written(v, f);
}
}  // namespace

void NcProgram::axes(LathePoint p, bool force_both) {
  const WrittenNumber x = written_after(last_x_, x_out(p.r), fmt_x_);
  const WrittenNumber z = written_after(last_z_, p.z, fmt_z_);
  // A word is left out when it would repeat the text written last.
  bool write_x = force_both || !m_.modal_words || !last_x_ || !same_text(*last_x_, x);
  bool write_z = force_both || !m_.modal_words || !last_z_ || !same_text(*last_z_, z);
  if (write_x) w_.word("X", x, fmt_x_);
  if (write_z) w_.word("Z", z, fmt_z_);
  last_x_ = x;
  last_z_ = z;
  pos_ = p;
  at_machine_position_ = false;
}

std::string NcProgram::feed_mode_code(FeedMode mode) const {
  const bool per_rev = mode == FeedMode::kPerRev;
  if (css_on_)
    return std::string(per_rev ? m_.control->css_feed_per_rev : m_.control->css_feed_per_min);
  return m_.code(per_rev ? "feed_per_rev" : "feed_per_min");
}

void NcProgram::feed_words() {
  if (!written_feed_mode_ || *written_feed_mode_ != feed_mode_) {
    w_.code(feed_mode_code(feed_mode_));
    written_feed_mode_ = feed_mode_;
    written_feed_.reset();
  }
  const WrittenNumber f = written_after(written_feed_, feed_, fmt_f_);
  if (!m_.modal_words || !written_feed_ || !same_text(*written_feed_, f)) {
    w_.word("F", f, fmt_f_);
    written_feed_ = f;
  }
}

bool NcProgram::stays_at(LathePoint p) const {
  return last_x_ && last_z_ && same_text(*last_x_, written_after(last_x_, x_out(p.r), fmt_x_)) &&
         same_text(*last_z_, written_after(last_z_, p.z, fmt_z_));
}

bool NcProgram::arc_has_no_radius(LathePoint center) const {
  if (!pos_) return false;
  const WrittenNumber i = written(center.r - pos_->r, fmt_i_);
  const WrittenNumber k = written(center.z - pos_->z, fmt_k_);
  return i.exact && k.exact && i.digits == 0 && k.digits == 0;
}

void NcProgram::rapid(LathePoint p) {
  if (stays_at(p)) return;
  motion_code(code_rapid_);
  axes(p, false);
  w_.end_block();
}

void NcProgram::linear(LathePoint p) {
  if (stays_at(p)) return;
  motion_code(code_linear_);
  axes(p, false);
  feed_words();
  w_.end_block();
}

void NcProgram::arc(LathePoint p, LathePoint center, bool ccw) {
  LathePoint from = pos_.value_or(p);
  motion_code(ccw ? code_arc_ccw_ : code_arc_cw_);
  axes(p, false);
  // Arc centres are incremental from the start point, as radii (I along X, K along Z).
  w_.word("I", center.r - from.r, fmt_i_);
  w_.word("K", center.z - from.z, fmt_k_);
  feed_words();
  w_.end_block();
}

void NcProgram::thread(LathePoint p, double lead, std::optional<double> start_angle) {
  ThreadLead l;
  l.lead = lead;
  l.start_angle = start_angle;
  thread(p, l);
}

void NcProgram::thread(LathePoint p, const ThreadLead& l) {
  LathePoint from = pos_.value_or(p);
  // The lead is along the axis that travels further (radius against Z, as the controls
  // measure the thread's angle).
  bool along_x =
      std::fabs(p.r - from.r) > std::fabs(p.z - from.z) && !m_.thread_lead_address_x.empty();
  const std::string& lead_addr = along_x ? m_.thread_lead_address_x : m_.thread_lead_address;
  if (l.lead_change != 0) {
    motion_code(m_.code(l.lead_change > 0 ? "thread_increasing" : "thread_decreasing"));
  } else {
    motion_code(code_thread_);
  }
  axes(p, false);
  if (l.tpi > 0 && !m_.tpi_address.empty()) {
    w_.word(m_.tpi_address, l.tpi);
  } else {
    w_.word(lead_addr, l.lead);
    if (lead_addr == "F") written_feed_.reset();
  }
  if (l.lead_change != 0) {
    w_.word("F", std::fabs(l.lead_change));
    written_feed_.reset();
  }
  // The start angle in the control's unit (format thread_angle: Fanuc and Haas Q in 0.001 degree
  // without a point, as G92's), else as the default format writes degrees (SINUMERIK SF=).
  if (l.start_angle && m_.start_angle_word)
    w_.word(m_.start_angle_address, *l.start_angle, m_.format_for("thread_angle"));
  w_.end_block();
}

TemplateWrite NcProgram::write_template(const TemplateValues& v) {
  return write_lines(w_, m_, v);
}

std::string NcProgram::num(std::string_view format, double v) const {
  return number_text(v, m_.format_for(format));
}

void NcProgram::cycle_ended_at(LathePoint p) {
  forget_modal();
  pos_ = p;
  at_machine_position_ = false;
}

void NcProgram::units_changed(double factor, bool inch) {
  if (units_copy_) use_units(*units_copy_, *units_loaded_, inch);
  if (pos_) pos_ = LathePoint{pos_->r * factor, pos_->z * factor};
  feed_ *= factor;
  last_x_.reset();
  last_z_.reset();
  written_feed_.reset();
}

void NcProgram::forget_modal() {
  motion_.clear();
  last_x_.reset();
  last_z_.reset();
  written_feed_.reset();
  written_feed_mode_.reset();
}

}  // namespace clpost
