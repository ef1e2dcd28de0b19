#pragma once
// A machine definition: plain data loaded from posts/<dialect>.yaml and machines/<name>.yaml
// (see machine_loader.h and docs/machines.md). Nothing about a machine is compiled in.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "machine/control.h"

namespace clpost {

// How one address's numbers are written.
struct NumberFormat {
  int decimals = 3;             // digits after the point (rounding)
  bool trailing_zeros = false;  // "1.500" rather than "1.5"
  bool decimal_point = true;    // "12." rather than "12" for whole numbers (ignored when
                                // decimals == 0: whole numbers only, no point)
  bool leading_zero = true;     // "0.5" rather than ".5"
  double scale = 1;             // value multiplied before writing (e.g. 1000 for micrometres)
  // Digits after the point in an inch program (formats.<a>.inch_decimals). The loader gives the
  // ones it leaves out a value: a length address (X, Z, I, K, R, U, W) takes the control's least
  // input increment in inch (Control::inch_length_increment) when that is finer, every other
  // `decimals`. -1 only in a machine made in code: `decimals`.
  int inch_decimals = -1;

  // This format as an inch (`inch` true) or metric program writes it.
  NumberFormat in_units(bool inch) const {
    NumberFormat f = *this;
    if (inch && inch_decimals >= 0) f.decimals = inch_decimals;
    return f;
  }
};

enum class ThreadStrategy : uint8_t { kCycle, kLoop, kEmulate };
enum class ThreadFallback : uint8_t { kLoop, kEmulate, kError };
// kAuto (cl.radial_axis only): the radial axis is found from the program (the one of the two
// non-axial axes that is not constantly 0).
enum class ClAxis : uint8_t { kX, kY, kZ, kAuto };
// How a control moves its C axis to an absolute C word (millturn.c_rotation).
enum class CRotation : uint8_t { kRollover, kContinuous };
// How the control takes X in polar interpolation (millturn.polar_x): not known (the mode is
// then not written), as a radius, as a diameter.
enum class PolarX : uint8_t { kUnknown, kRadius, kDiameter };

// A length a machine file gives as a number, or as `auto`: clpost works it out.
struct LengthOrAuto {
  bool automatic = false;
  double value = 0;  // when not automatic
};

struct Machine {
  std::string name;         // machine file stem, e.g. "generic-lathe"
  std::string post;         // the post (dialect) it extends, e.g. "iso-lathe"
  std::string description;  // one line, for `clpost machines`
  std::string source;       // machine file path (diagnostics)

  // CL frame
  std::string default_units = "mm";  // when the CL file has no UNITS statement: mm | in
  ClAxis cl_radial = ClAxis::kAuto;  // CL axis holding the lathe's radial coordinate
  ClAxis cl_axial = ClAxis::kZ;      // CL axis holding the spindle axis
  bool cl_x_is_diameter = false;     // CL radial values are diameters already
  // SPINDL/…,SFM|SMM: false (`file`): a surface speed in the file's unit per minute whatever
  // the word (CATIA); true (`word`): SFM is feet, SMM metres per minute, converted (NX, ICAM).
  bool surface_speed_by_word = false;
  bool diameter_output = true;  // write X as a diameter

  // Limits (0 = none)
  double max_rpm = 0;
  double max_feed = 0;    // per minute, output units
  double max_feed_x = 0;  // per axis (X as a radius), per minute; 0 = max_feed
  double max_feed_z = 0;

  // Threading
  ThreadStrategy thread_strategy = ThreadStrategy::kEmulate;
  ThreadFallback thread_fallback = ThreadFallback::kEmulate;
  int default_option = 0;
  double default_tool_angle = 60;
  bool start_angle_word = false;          // the control's thread block has a start-angle word
  bool variable_lead = false;             // G34/G35 style variable lead
  std::string thread_lead_address = "F";  // G33 lead word (F, K, ...)
  std::string start_angle_address = "Q";  // when start_angle_word
  // The control threading.cycle selects (null: "none", plain ISO), from `controls`: the set the
  // machine was loaded with (the registry's, or a test's own).
  const Control* control = nullptr;
  ControlSet controls;
  // The values of the keys the set's controls declare (Control::keys), at the slots schema()
  // gives them (machine_schema.h: ControlSlot), and the slot of m.control's first:
  // control_value() (control.h) reads them.
  std::vector<double> control_values;
  uint32_t own_keys_at = 0;
  // The loop block threading.loop selects from the set's (null: g33, the G33 loop).
  const LoopBlock* thread_loop = nullptr;
  std::string thread_lead_address_x;  // lead word when the X travel dominates ("" = same)
  std::string tpi_address;            // threads-per-inch word used when the CL gave TPI ("" none)
  LengthOrAuto run_in;                // threading.run_in: the cycle words' run-in, or auto
  bool extra_spring_passes = false;   // a cycle may add full-depth passes the plan lacks
  double thread_tolerance = 0;        // largest cut difference that counts as exact, CL units
                                      // (0 = one least increment of the Z format)
  // G76 cycles with flank infeed (their controls' laws); the pass-end rule is unverified.
  bool cycle_shifted_end = false;  // threading.cycle_pass_end: shifted (else fixed: every pass
                                   // ends at the cycle's Z)
  bool accept_pass_end = false;    // a fixed pass end may differ from the plan's (noted)
  double chamfer_angle = 45;       // the control's thread chamfer angle (a parameter of it)
  // How the lead axis follows the spindle into and out of a synchronized cut (the law of
  // planner/run_in.h): its servo time constant T1 in seconds, and the lead error a (a fraction
  // of the lead) below which the lead counts as right.
  double servo_time_constant = 0.033;
  double lead_error = 0.01;

  // Holes on the spindle axis (CYCLE/DRILL …)
  bool rigid_tapping = false;   // CYCLE/TAP uses hole_tap_rigid
  double peck_clearance = 0.5;  // expanded pecks: re-entry clearance, chip-break back-off
  bool tap_turns_cw = false;    // the tap cycle starts the spindle M3 itself (some G84s)

  // Output
  std::string extension = ".nc";
  std::string line_ending = "\n";
  std::string comment_open = "(";
  std::string comment_close = ")";
  bool comment_upper = false;            // upper-case comment text
  int comment_max_length = 0;            // longer comment text is wrapped (0: no limit)
  int max_line_length = 0;               // a longer block is an error (0: no limit)
  std::string comment_forbidden = "()";  // characters removed from comment text
  bool block_numbers = false;
  bool numbers_at_tool_changes = false;  // number only the first block of each tool change
  std::string block_address = "N";
  int block_start = 10;
  int block_step = 10;
  int block_max = 99999;                             // wraps to block_start after this
  std::vector<std::string> block_skip = {"%", "O"};  // blocks starting so get no number
  bool modal_codes = true;                           // suppress repeated modal G codes
  bool modal_words = true;                           // suppress unchanged X/Z/F/S words
  int program_number = 1;
  std::string block_delete = "/";  // starts a block the operator may skip (OPSKIP)

  // Mill-turn (docs/millturn.md): what the lathe has besides X and Z. The codes and templates
  // that drive them are machine data too (codes.live_spindle_cw …, templates.live_spindle_rpm …).
  bool live_tools = false;      // driven (milling) tools: a milling tool is an error without them
  bool c_axis = false;          // the main spindle positions as a C axis (ROTABL/…,CAXIS)
  bool y_axis = false;          // a Y axis on the turret
  bool face_holes = false;      // hole cycles off the centre line on the face at the C index
  double live_max_rpm = 0;      // the live spindle's speed limit (0: none)
  std::string c_address = "C";  // the C axis word
  // How the control takes an absolute C word: kRollover, an angle 0 <= C < 360 that it reaches
  // the shortest way; kContinuous, a continuous angle (C360 is one turn more than C0).
  CRotation c_rotation = CRotation::kRollover;
  bool c_clw_increasing = false;  // a CLW turn (ROTABL/…,CLW) increases C (else decreases it)
  // Face milling without Y (XZC, interpreter/milling_motion.cc): the chordal tolerance of the
  // pieces a part-frame line is split into, output units; the feed of a move that turns C is
  // written in inverse time (codes.inverse_time, G93) or as the combined feed of X, Z and C
  // (degrees counted as output units).
  double xzc_tolerance = 0.005;
  bool xzc_inverse_time = false;
  // Face milling in the control's polar interpolation (interpreter/milling_polar.cc): asked for
  // (codes polar_on, polar_off), the word of its virtual axis (Fanuc C, Haas Y; empty: not
  // known) and how X is taken in it. Written only when all are known.
  bool polar_interpolation = false;
  std::string polar_address;
  PolarX polar_x = PolarX::kUnknown;
  double polar_rapid_feed = 0;  // a RAPID in the mode: G1 at this feed (0: the rapid code)
  bool polar_arcs = false;      // arcs in the mode as G2/G3 (else chords within xzc_tolerance)

  // Cycle time (0: not known)
  double rapid_x = 0;           // per minute along X (as a radius), output units
  double rapid_z = 0;           // per minute along Z
  double tool_change_time = 0;  // seconds
  double rapid_c = 0;           // degrees per minute of the C axis (0: C moves are not timed)
  double c_clamp_time = 0;      // seconds each C clamp or unclamp code takes

  std::map<std::string, NumberFormat> formats;  // by address; "default" for the others
  std::map<std::string, std::string> codes;     // rapid, linear, arc_cw, ... -> "G0", ...
  // Block templates (fmt replacement fields with named arguments), one NC line each.
  std::map<std::string, std::vector<std::string>> templates;

  // The format of `address` (else "default"): a metric program's, or the program's units' in a
  // post's own copy of the machine (writer/unit_formats.h).
  const NumberFormat& format_for(std::string_view address) const;
  const std::string& code(const std::string& key) const;  // empty when absent
};

// Makes `copy`, a post's own copy of machine `loaded`, write numbers as a program in inch
// (`inch`) or metric does: its formats become loaded's in those units (in place: references to
// them stay valid). NcProgram calls it at the program's start and at every units code.
void use_units(Machine& copy, const Machine& loaded, bool inch);

// What a radius is multiplied by to be an X value (and an X value divided by to be a radius):
// 2 where X is a diameter, 1 where it is a radius. `diameter` is whichever flag says so: the
// machine's output.diameter (below), the simulated control's modal G7/G8 state, the CL's
// cl.x_is_diameter.
constexpr double diameter_factor(bool diameter) {
  return diameter ? 2 : 1;
}
// Machine `m`'s: X is written as a diameter with output.diameter.
inline double diameter_factor(const Machine& m) {
  return diameter_factor(m.diameter_output);
}

// Whether `m` writes a program_header (an empty list writes none). Its program is then written
// only once the whole CL file is posted (interpreter/post.h).
bool writes_program_header(const Machine& m);

}  // namespace clpost
