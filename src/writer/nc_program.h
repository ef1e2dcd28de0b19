#pragma once
// The NC program being written: modal state (motion code, feed mode, feed, spindle, position)
// over NcWriter, so that callers say what the machine should do and only what changes is
// written. Coordinates are in the lathe frame: `r` is a radius, `z` the spindle axis, in output
// units; diameter output is applied here.
#include <optional>
#include <string>
#include <string_view>

#include "machine/machine.h"
#include "machine/template_values.h"
#include "writer/nc_writer.h"

namespace clpost {

enum class SpindleDir { kCw, kCcw };
enum class FeedMode { kPerMinute, kPerRev };
enum class Coolant { kOff, kFlood, kMist, kThrough, kAir };
enum class CutterComp { kOff, kLeft, kRight };

struct LathePoint {
  double r = 0;
  double z = 0;
};

// The words of one synchronized move besides its end point.
struct ThreadLead {
  double lead = 0;                    // output units per revolution
  std::optional<double> start_angle;  // degrees; written only when the machine has the word
  double tpi = 0;                     // > 0: the CL gave threads per inch (machine tpi_address)
  double lead_change = 0;             // variable lead: change per revolution (+ INCR, - DECR)
};

// How writing a template went. Every caller handles it: a template that cannot be written is
// an error, never a block silently left out.
struct [[nodiscard]] TemplateWrite {
  enum class Status : uint8_t {
    kWritten,  // written (an empty list of lines, the integrator's choice, writes nothing)
    kMissing,  // the machine has no such template
    kNoValue,  // a line needs a field the caller could not give (`field`)
    kBadLine   // fmt could not format a line (`detail`)
  };
  Status status = Status::kWritten;
  std::string_view name;   // the template
  std::string_view field;  // kNoValue
  std::string detail;      // kBadLine
  explicit operator bool() const { return status == Status::kWritten; }
};

// "machine 'm' has no template 'spindle_css'", "machine 'm': template 'dwell' needs
// {revolutions}, which is not known here", … (for an error at the CL line or thread).
std::string template_error(const Machine& m, const TemplateWrite& w);

class NcProgram {
 public:
  NcProgram(const Machine& m, Sink& out);

  NcWriter& writer() { return w_; }
  const Machine& machine() const { return m_; }

  // program_start / program_end templates.
  [[nodiscard]] TemplateWrite start(std::string_view program_name, bool inch,
                                    std::string_view file);
  [[nodiscard]] TemplateWrite end(std::string_view program_name);

  [[nodiscard]] TemplateWrite tool_change(int tool, int offset, std::string_view name);
  // The code that sets feed mode `mode`: codes.feed_per_min or feed_per_rev, or under constant
  // surface speed on a control whose feed type and spindle mode are one G group its codes that
  // keep it (Control::css_feed_per_min, css_feed_per_rev: SINUMERIK's G961, G96).
  std::string feed_mode_code(FeedMode mode) const;
  [[nodiscard]] TemplateWrite spindle_rpm(double rpm, SpindleDir dir);
  [[nodiscard]] TemplateWrite spindle_css(double speed, double max_rpm, SpindleDir dir);
  [[nodiscard]] TemplateWrite spindle_stop();
  void coolant(Coolant c);
  void cutter_comp(CutterComp c);
  // The feed for the next feed moves; written with the next feed move when it changed.
  void set_feed(double feed, FeedMode mode);
  // A dwell through the machine's `dwell` template, whose fields are {seconds} and
  // {revolutions}. A value may be unknown (no spindle speed in RPM to convert through): kNoValue,
  // and nothing written, when the template needs it.
  [[nodiscard]] TemplateWrite dwell(std::optional<double> seconds,
                                    std::optional<double> revolutions);
  void program_stop(bool optional);
  void comment(std::string_view text) { w_.comment(text); }
  void raw(std::string_view text) { w_.raw_line(text); }

  // A rapid or feed move; none at all to where the program has just put the tool (its X and Z
  // would be written as they were last): a block of its motion code alone moves nothing.
  void rapid(LathePoint p);
  void linear(LathePoint p);
  // Arc in the XZ plane to `p` around `center`; `ccw` = positive rotation about +Y (G3 in G18).
  void arc(LathePoint p, LathePoint center, bool ccw);
  // One synchronized (thread) move; `lead` is written with the post's lead address.
  // `start_angle` adds the start-angle word when the machine has one.
  void thread(LathePoint p, double lead, std::optional<double> start_angle = std::nullopt);
  // The same with every lead word: the lead goes to threading.lead_address, or
  // threading.lead_address_x when the X travel dominates; with a TPI and a tpi_address the
  // thread count per inch of the lead is written instead; a lead change selects the codes
  // thread_increasing / thread_decreasing (G34 / G35) with the change in the F format.
  void thread(LathePoint p, const ThreadLead& l);

  // Writes the machine's template `v.spec()`, one block per line, with the fields of `v` (numbers
  // already formatted with num()). Writes nothing unless every line can be written.
  [[nodiscard]] TemplateWrite write_template(const TemplateValues& v);
  // `v` as the machine writes numbers of format `format` (an address or a named format).
  std::string num(std::string_view format, double v) const;
  // After a cycle: the tool is at `p` (lathe frame, output units); modal words are unknown.
  void cycle_ended_at(LathePoint p);

  // `p` is where the program has just put the tool: its X and Z as last written.
  bool stays_at(LathePoint p) const;
  // An arc around `center` from where the tool is would be written with I and K both zero: the
  // written centre is the start, an arc of no radius (a full circle or an alarm on the control).
  bool arc_has_no_radius(LathePoint center) const;
  // Where the tool is (unknown until the first move).
  std::optional<LathePoint> position() const { return pos_; }
  // Forgets the modal motion code, feed and spindle words (after a cycle or raw insert whose
  // effect on them is unknown).
  void forget_modal();
  // The blocks just written (a home return, G28 U0.) put the tool at a machine position the
  // program does not state, until its next move: modal words forgotten, and no arc can start
  // there (its I and K would be measured from a point the control is not at).
  void to_machine_position() {
    forget_modal();
    at_machine_position_ = true;
  }
  bool is_at_machine_position() const { return at_machine_position_; }
  // After a units code (G20/G21): the control reads later numbers in the new units, so the
  // position and the feed are converted by `factor` (new units per old) and the next move writes
  // X, Z and F in full.
  // `inch`: the new units are inches (the formats follow them, see follow_units).
  void units_changed(double factor, bool inch);
  // The numbers follow the program's units: `copy` (the machine this program writes with, a
  // post's own copy of `loaded`) takes loaded's formats in the units of the start and of every
  // units code (use_units).
  void follow_units(Machine& copy, const Machine& loaded) {
    units_copy_ = &copy;
    units_loaded_ = &loaded;
  }

 private:
  void motion_code(const std::string& code);
  void axes(LathePoint p, bool force_both);

  void feed_words();
  void spindle_mode_written(bool css);
  double x_out(double r) const { return diameter_factor(m_) * r; }

  const Machine& m_;
  Machine* units_copy_ = nullptr;  // follow_units
  const Machine* units_loaded_ = nullptr;
  NcWriter w_;
  // Looked up once: the formats and codes of every move.
  const NumberFormat& fmt_x_;
  const NumberFormat& fmt_z_;
  const NumberFormat& fmt_f_;
  const NumberFormat& fmt_i_;
  const NumberFormat& fmt_k_;
  const std::string& code_rapid_;
  const std::string& code_linear_;
  const std::string& code_arc_cw_;
  const std::string& code_arc_ccw_;
  const std::string& code_thread_;
  std::optional<LathePoint> pos_;
  bool at_machine_position_ = false;
  std::string motion_;                            // last motion code written
  std::optional<WrittenNumber> last_x_, last_z_;  // as last written
  double feed_ = 0;
  FeedMode feed_mode_ = FeedMode::kPerMinute;
  std::optional<WrittenNumber> written_feed_;
  std::optional<FeedMode> written_feed_mode_;
  bool css_on_ = false;  // the control's group 15 is at constant surface speed (Control)
};

}  // namespace clpost
