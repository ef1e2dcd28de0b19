#include "machine/machine_schema.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <type_traits>

#include "machine/control.h"
#include "support/json_text.h"

namespace clpost {
namespace {

using M = Machine;
using enum KeyType;

constexpr Choice kUnits[] = {{"mm", "mm"}, {"in", "in"}};
constexpr Choice kAxes[] = {{"x"}, {"y"}, {"z"}};                  // ClAxis order
constexpr Choice kRadialAxes[] = {{"x"}, {"y"}, {"z"}, {"auto"}};  // ClAxis order
constexpr Choice kLineEndings[] = {{"lf", "\n"}, {"crlf", "\r\n"}};
constexpr Choice kStrategies[] = {{"cycle"}, {"loop"}, {"emulate"}};   // ThreadStrategy order
constexpr Choice kFallbacks[] = {{"loop"}, {"emulate"}, {"error"}};    // ThreadFallback order
constexpr Choice kSurfaceSpeed[] = {{"file"}, {"word"}};               // false, true
constexpr Choice kPassEnds[] = {{"fixed"}, {"shifted"}};               // false, true
constexpr Choice kCRotations[] = {{"rollover"}, {"continuous"}};       // CRotation order
constexpr Choice kClwTurns[] = {{"decreasing"}, {"increasing"}};       // false, true
constexpr Choice kXzcFeeds[] = {{"combined"}, {"inverse_time"}};       // false, true
constexpr Choice kPolarX[] = {{"unknown"}, {"radius"}, {"diameter"}};  // PolarX order

constexpr const char* kId = "Identity";
constexpr const char* kCl = "CL frame";
constexpr const char* kOut = "Output";
constexpr const char* kLim = "Limits";
constexpr const char* kThr = "Threading";
constexpr const char* kFacts = "Control facts";
constexpr const char* kHoles = "Holes";
constexpr const char* kTime = "Cycle time";
constexpr const char* kMillTurn = "Mill-turn";

// Every key of a post or machine file (sections in docs order).
// The keys before the controls' own.
constexpr KeySpec kEarlierKeys[] = {
    {"extends",
     kId,
     kString,
     &M::post,
     "the post (dialect) this machine builds on, from posts/; machine files only",
     0,
     0,
     {},
     true},
    {"description", kId, kString, &M::description, "one line for `clpost machines`"},
    {"units", kId, kChoice, &M::default_units, "CL units when the CL file has no UNITS statement",
     0, 0, kUnits},
    {"cl.radial_axis", kCl, kChoice, &M::cl_radial,
     "the CL axis that holds the lathe's radial coordinate; `auto`: the one of the two others than "
     "the axial axis that is not constantly 0, found at the first point off the axis (a note says "
     "which; a program that moves in both is an error)",
     0, 0, kRadialAxes},
    {"cl.axial_axis", kCl, kChoice, &M::cl_axial, "the CL axis that holds the spindle axis", 0, 0,
     kAxes},
    {"cl.radial_is_diameter", kCl, kBool, &M::cl_x_is_diameter,
     "CL radial values are diameters already"},
    {"cl.surface_speed", kCl, kChoice, &M::surface_speed_by_word,
     "what SPINDL/…,SFM or SMM means: `file`: a surface speed in the CL file's unit per minute "
     "(m/min "
     "in a metric file) whatever the word, as CATIA V5 writes it; `word`: SFM is ft/min and SMM "
     "m/min, converted to the program's unit (docs/reading-cam-output.md)",
     0, 0, kSurfaceSpeed},
    {"output.extension", kOut, kString, &M::extension,
     "file extension of the NC program (batch mode names outputs with it)"},
    {"output.line_ending", kOut, kChoice, &M::line_ending, "line ending of the NC program", 0, 0,
     kLineEndings},
    {"output.diameter", kOut, kBool, &M::diameter_output, "write X as a diameter"},
    {"output.modal_codes", kOut, kBool, &M::modal_codes,
     "leave out a G code that is already in force"},
    {"output.modal_words", kOut, kBool, &M::modal_words,
     "leave out an X, Z, F or S word that has not changed"},
    {"output.program_number", kOut, kInt, &M::program_number,
     "the `{program_number}` of the start and end templates", 0, 99999999},
    {"comments.open", kOut, kString, &M::comment_open, "what opens a comment (`; ` for Siemens)"},
    {"comments.close", kOut, kString, &M::comment_close,
     "what closes a comment (empty for Siemens)"},
    {"comments.upper_case", kOut, kBool, &M::comment_upper, "upper-case comment text"},
    {"comments.forbidden", kOut, kString, &M::comment_forbidden,
     "characters removed from comment text"},
    {"comments.max_length", kOut, kInt, &M::comment_max_length,
     "the longest comment text the control takes: longer text is wrapped onto more comment "
     "blocks, with a warning (0: no limit)",
     0, 10000},
    {"output.max_line_length", kOut, kInt, &M::max_line_length,
     "the longest block the control takes, in characters: a longer one is an error (0: no limit)",
     0, 100000},
    {"output.block_delete", kOut, kString, &M::block_delete,
     "what starts a block the operator may skip, between OPSKIP/ON and OPSKIP/OFF (`/`); empty: "
     "OPSKIP is a warning"},
    {"block_numbers.enabled", kOut, kBool, &M::block_numbers, "number the blocks"},
    {"block_numbers.at_tool_changes", kOut, kBool, &M::numbers_at_tool_changes,
     "with `enabled`, number only the first block of each tool change: the sequence numbers an "
     "operator restarts a program at"},
    {"block_numbers.address", kOut, kString, &M::block_address, "the block number's address"},
    {"block_numbers.start", kOut, kInt, &M::block_start, "the first block number", 0, 99999999},
    {"block_numbers.step", kOut, kInt, &M::block_step, "the step between block numbers", 1, 1000},
    {"block_numbers.max", kOut, kInt, &M::block_max,
     "the largest block number; numbering wraps to `start` after it", 1, 99999999},
    {"block_numbers.skip", kOut, kList, &M::block_skip,
     "blocks starting with one of these get no number"},
    {"limits.max_rpm", kLim, kNumber, &M::max_rpm,
     "a spindle speed above it is an error at the CL line; CSS writes it as the speed clamp (0: "
     "none)",
     0, 1e6},
    {"limits.max_feed", kLim, kNumber, &M::max_feed,
     "per minute, output units; a thread whose lead × rpm exceeds it is an error (0: none)", 0,
     1e7},
    {"limits.max_feed_x", kLim, kNumber, &M::max_feed_x,
     "per minute along X (as a radius); a thread moving X faster is an error (0: max_feed)", 0,
     1e7},
    {"limits.max_feed_z", kLim, kNumber, &M::max_feed_z,
     "per minute along Z; a thread moving Z faster is an error (0: max_feed)", 0, 1e7},
    {"threading.strategy", kThr, kChoice, &M::thread_strategy,
     "what to try first: the control's multi-pass cycle, its single-pass loop block, or plain "
     "G1/G33 emulation",
     0, 0, kStrategies},
    // Its choices are the set's (schema()).
    {"threading.cycle", kThr, kChoice, &M::control,
     "which cycle `strategy: cycle` writes (it needs the template of that name)"},
    // Its choices are the set's (schema()).
    {"threading.loop", kThr, kChoice, &M::thread_loop,
     "the loop block: G33 chains (Siemens, NCT, LinuxCNC, Heidenhain) or Fanuc G92 (templates g92 "
     "and g92_next)"},
    {"threading.fallback", kThr, kChoice, &M::thread_fallback,
     "what to write when the first choice would not cut the plan exactly", 0, 0, kFallbacks},
    {"threading.tolerance", kThr, kNumber, &M::thread_tolerance,
     "the largest difference between a cut the control makes and the planned one that still "
     "counts as exact, CL units; 0 means one least increment of the Z format",
     0, 1},
    {"threading.extra_spring_passes", kThr, kBool, &M::extra_spring_passes,
     "accept a cycle that adds full-depth passes the plan lacks (Fanuc's m ≥ 1); the NC says so "
     "in a comment"},
    {"threading.option", kThr, kInt, &M::default_option, "OPTION when the CL gives none", 0, 4},
    {"threading.tool_angle", kThr, kNumber, &M::default_tool_angle,
     "TLANGL when the CL gives none, degrees", 1e-9, 179.999999},
    {"threading.lead_address", kThr, kString, &M::thread_lead_address,
     "the lead word of a thread block (`K` for LinuxCNC and Siemens)"},
    {"threading.lead_address_x", kThr, kString, &M::thread_lead_address_x,
     "the lead word when the X travel dominates (Siemens `I`; empty: lead_address)"},
    {"threading.tpi_address", kThr, kString, &M::tpi_address,
     "a threads-per-inch word used when the CL gave TPI (NCT `E`; empty: none)"},
    {"threading.start_angle_word", kThr, kBool, &M::start_angle_word,
     "the thread block has a spindle start-angle word, so multi-start threads use it instead of "
     "shifting the start"},
    {"threading.start_angle_address", kThr, kString, &M::start_angle_address,
     "that word (`SF=` on Siemens)"},
    {"threading.variable_lead", kThr, kBool, &M::variable_lead,
     "the control cuts INCR/DECR leads (G34/G35); otherwise such a CL thread is an error"},
    {"threading.run_in", kThr, kNumberOrAuto, &M::run_in,
     "run-in written into cycle words that have one (CYCLE99 `APP`, G31 `B`), taken from the "
     "start of the CL's thread; `auto`: the run-in δ1 of the servo law (docs/threading.md "
     "section 15) is added before the CL's start in every output, and written there (APP, "
     "CYCLE98 `APP`, G31 `B`; G31 `P` gets the run-out δ2)",
     0, 1000},
    {"threading.chamfer_angle", kFacts, kNumber, &M::chamfer_angle,
     "the control's thread chamfer angle, degrees (Fanuc parameter 5131, Haas setting 96)", 1, 89},
    {"threading.cycle_pass_end", kFacts, kChoice, &M::cycle_shifted_end,
     "how a G76 with flank infeed ends its passes: `fixed`, every pass ends at the Z word "
     "(Fanuc's figure); `shifted`, each pass moves as a whole (LinuxCNC) *(unverified for Fanuc)*",
     0, 0, kPassEnds},
    {"threading.accept_pass_end", kFacts, kBool, &M::accept_pass_end,
     "with `fixed`, accept that shallower flank passes end at Z rather than where the plan ends "
     "them; the NC says so in a comment"},
    {"threading.servo_time_constant", kFacts, kNumber, &M::servo_time_constant,
     "T1, the time constant of the feed axes' servo, seconds: the lead is not yet right over "
     "the first δ1 = T1·V·(a − 1 − ln a) and no longer right over the last δ2 = T1·V of every "
     "synchronized cut, V = rpm × lead / 60 (Fanuc Series 15i operator's manual, appendix "
     "\"Incorrect threaded length\": usually 0.033 s; docs/threading.md section 15)",
     0, 1},
    {"threading.lead_error", kFacts, kNumber, &M::lead_error,
     "a, the lead error that still counts as a right lead, a fraction of the lead (0.01: 1 %), "
     "in the same law (Fanuc Series 15i, appendix \"Incorrect threaded length\")",
     1e-4, 0.5},
};

// The keys after the controls' own.
constexpr KeySpec kLaterKeys[] = {
    {"holes.rigid_tapping", kHoles, kBool, &M::rigid_tapping,
     "the spindle is synchronised for tapping: CYCLE/TAP uses template hole_tap_rigid (Fanuc "
     "M29, LinuxCNC G33.1)"},
    {"holes.peck_clearance", kHoles, kNumber, &M::peck_clearance,
     "where moves written for pecks stop short of the last depth when they go back in, and how "
     "far a chip-breaking peck backs off, output units (the control's own setting in a cycle: "
     "Fanuc parameter 5114)",
     0, 100},
    {"holes.tap_turns_cw", kHoles, kBool, &M::tap_turns_cw,
     "the tap cycle turns the spindle clockwise itself (Haas G84): a left-hand tap (SPINDL/…,CCLW) "
     "is then written as moves"},
    {"millturn.live_tools", kMillTurn, kBool, &M::live_tools,
     "the turret has driven (live) tools: a milling tool (LOADTL/…,MILL, TDATA/MILL, …) turns "
     "them through templates live_spindle_rpm and live_spindle_stop; without them a milling tool "
     "is an error at its LOADTL (docs/millturn.md)"},
    {"millturn.c_axis", kMillTurn, kBool, &M::c_axis,
     "the main spindle positions as a C axis: ROTABL/a,…,CAXIS writes template c_index between "
     "codes c_engage/c_unclamp and c_clamp; without it such a ROTABL is an error"},
    {"millturn.y_axis", kMillTurn, kBool, &M::y_axis,
     "the turret has a Y axis: a live tool's face milling is written in the face plane (codes "
     "plane_face, plane_lathe) as X (diameter) Y Z moves and G2/G3 arcs at the C index; without "
     "it the post computes X Z C (docs/millturn.md)"},
    {"millturn.face_holes", kMillTurn, kBool, &M::face_holes,
     "a live tool drills off the centre line on the face: a hole cycle's GOTO at (x, y) with "
     "the tool axis along Z is written by the hole_* templates at X = hypot(x, y) with C = the "
     "ROTABL index + atan2(y, x); without it such a hole is an error naming what is missing "
     "(radial holes need no key: templates hole_radial_*, else moves; docs/millturn.md)"},
    {"millturn.live_max_rpm", kMillTurn, kNumber, &M::live_max_rpm,
     "the live tool's speed limit: a milling tool's SPINDL above it is an error (0: none)", 0, 1e6},
    {"millturn.c_address", kMillTurn, kString, &M::c_address,
     "the C axis word (`C`): template c_index's {address}"},
    {"millturn.c_rotation", kMillTurn, kChoice, &M::c_rotation,
     "how the control takes an absolute C word: `rollover`, an angle 0 <= C < 360 reached the "
     "shortest way (a turn the CL gives the other way, or of 180 degrees or more, is written as "
     "steps under 180 degrees); `continuous`, a continuous angle (C370 is C10 one turn on), "
     "written as the last C plus the turn",
     0, 0, kCRotations},
    {"millturn.c_clw", kMillTurn, kChoice, &M::c_clw_increasing,
     "what a CLW turn (ROTABL/…,CLW) does to C: `decreasing` (clockwise seen from +Z, the "
     "right-hand rule about +Z; inferred, as no CAM source states it) or `increasing`",
     0, 0, kClwTurns},
    {"millturn.xzc_tolerance", kMillTurn, kNumber, &M::xzc_tolerance,
     "face milling without Y (XZC): the largest distance, output units, between the part-frame "
     "line of the CL and the path of the X, Z and C moves written for it (each CL line is split "
     "into pieces within it; docs/millturn.md)",
     1e-6, 10},
    {"millturn.xzc_feed", kMillTurn, kChoice, &M::xzc_inverse_time,
     "how the control takes F on a move that turns C (XZC): `inverse_time`, F is 1/minutes of "
     "the move in code inverse_time (G93; LinuxCNC: rs274 completes the move in 1/F minutes); "
     "`combined`, F per minute of the combined move of X (as a radius), Z and C (degrees counted "
     "as length units; inferred for Fanuc, check the control's manual): written so that the tool "
     "moves along the part at the CL's feed",
     0, 0, kXzcFeeds},
    {"millturn.polar_interpolation", kMillTurn, kBool, &M::polar_interpolation,
     "face milling (tool axis 0,0,1) in the control's polar interpolation: C to 0, code "
     "polar_on, X and the virtual axis (polar_address) in the face plane at C0, G1 and G2/G3 "
     "exact, code polar_off; written only with polar_address and polar_x known, else an error "
     "at the first milling motion naming what is missing. Cylindrical interpolation is not "
     "written. false (the default): the post computes XZC (or X Y Z with Y) itself"},
    {"millturn.polar_address", kMillTurn, kString, &M::polar_address,
     "the word of the virtual axis in polar interpolation, across X in the face plane (Fanuc "
     "G12.1: `C`, the rotary axis's address; Haas G112: `Y`); empty: not known"},
    {"millturn.polar_x", kMillTurn, kChoice, &M::polar_x,
     "how the control takes X (and nothing else: the virtual axis and I, J are radii) in polar "
     "interpolation: `radius`, `diameter`, or `unknown` (the default: the mode is not written)",
     0, 0, kPolarX},
    {"millturn.polar_rapid_feed", kMillTurn, kNumber, &M::polar_rapid_feed,
     "a RAPID in polar interpolation is written as a G1 at this feed per minute, output units "
     "(for a control that takes no G0 in the mode: Fanuc's lists none among the G codes of "
     "G12.1); 0 (the default): the rapid code",
     0, 1e6},
    {"millturn.polar_arcs", kMillTurn, kBool, &M::polar_arcs,
     "the control takes G2/G3 (I, J in the plane) in polar interpolation: CIRCLE/ arcs about Z "
     "are written so, at most 120 degrees each; false (the default): as chords, each within "
     "half of millturn.xzc_tolerance of the arc, each an exact G1"},
    {"time.rapid_x", kTime, kNumber, &M::rapid_x,
     "rapid rate along X (as a radius), per minute, output units; 0: rapids are not timed", 0, 1e7},
    {"time.rapid_z", kTime, kNumber, &M::rapid_z,
     "rapid rate along Z, per minute, output units; 0: rapids are not timed", 0, 1e7},
    {"time.tool_change", kTime, kNumber, &M::tool_change_time,
     "seconds a tool change takes (turret index), added for every LOADTL", 0, 3600},
    {"time.rapid_c", kTime, kNumber, &M::rapid_c,
     "rapid rate of the C axis, degrees per minute: each C index and each hole's C move takes "
     "the angle turned over it; 0: C moves are not timed (and the cycle time says so)",
     0, 1e8},
    {"time.c_clamp", kTime, kNumber, &M::c_clamp_time,
     "seconds each C clamp or unclamp (codes.c_clamp, c_unclamp) takes, added for every one "
     "written",
     0, 3600},
};

const FormatKeySpec kFormatKeys[] = {
    {"decimals", kInt, &NumberFormat::decimals,
     "digits after the point; the value is rounded to them", 0, 9},
    {"trailing_zeros", kBool, &NumberFormat::trailing_zeros, "`1.500` rather than `1.5`"},
    {"decimal_point", kBool, &NumberFormat::decimal_point,
     "`12.` rather than `12` for whole numbers"},
    {"leading_zero", kBool, &NumberFormat::leading_zero, "`0.5` rather than `.5`"},
    {"inch_decimals", kInt, &NumberFormat::inch_decimals,
     "digits after the point in an inch program (G20/G700); default: for X, Z, I, K, R, U and W "
     "the control's least input increment in inch where it is finer than `decimals` (0.0001 in: "
     "4 on Fanuc, Haas, SINUMERIK and HEIDENHAIN), else `decimals`",
     0, 9, "see its meaning"},
    {"scale", kNumber, &NumberFormat::scale,
     "multiply before writing (1000: micrometres as integers, with `decimals: 0`)", 1e-6, 1e6},
};

// The codes before the controls' own.
constexpr NameSpec kEarlierCodes[] = {
    {"rapid", "rapid move (G0)", true},
    {"linear", "feed move (G1)", true},
    {"arc_cw", "clockwise arc (G2)", true},
    {"arc_ccw", "counter-clockwise arc (G3)", true},
    {"thread", "synchronized (thread) move (G33, G32)", true},
    {"metric", "millimetre input (G21, G710): the start template's {units_code}", true},
    {"inch", "inch input (G20, G700)", true},
    {"spindle_cw", "spindle clockwise (M3): the spindle templates' {direction}", true},
    {"spindle_ccw", "spindle counter-clockwise (M4)", true},
    {"feed_per_min", "feed per minute (G94, G98)"},
    {"feed_per_rev", "feed per revolution (G95, G99)"},
    {"coolant_off", "COOLNT/OFF (M9)"},
    {"coolant_flood", "COOLNT/FLOOD, ON (M8); a coolant the machine lacks becomes a comment"},
    {"coolant_mist", "COOLNT/MIST (M7)"},
    {"coolant_through", "COOLNT/THRU"},
    {"coolant_air", "COOLNT/AIR"},
    {"comp_off", "CUTCOM/OFF (G40)"},
    {"comp_left", "CUTCOM/LEFT (G41)"},
    {"comp_right", "CUTCOM/RIGHT (G42)"},
    {"stop", "STOP (M0)"},
    {"optional_stop", "OPSTOP (M1)"},
    {"thread_increasing", "variable lead, increasing (G34)"},
    {"thread_decreasing", "variable lead, decreasing (G35)"},
};

// The codes after the controls' own.
constexpr NameSpec kLaterCodes[] = {
    {"live_spindle_cw", "live tool clockwise (Haas M133): live_spindle_rpm's {direction}"},
    {"live_spindle_ccw", "live tool counter-clockwise (Haas M134)"},
    {"c_engage", "the main spindle becomes the C axis (Haas M154), before C first moves"},
    {"c_disengage", "the C axis becomes the main spindle again (Haas M155), before it turns"},
    {"c_clamp", "C axis brake on (Haas M14), after C is positioned"},
    {"c_unclamp", "C axis brake off (Haas M15), before C moves"},
    {"inverse_time",
     "inverse time feed (G93), for the XZC moves that turn C with millturn.xzc_feed: "
     "inverse_time; the next feed move writes feed_per_min again"},
    {"plane_face", "the face plane (G17), before milling in X Y (millturn.y_axis)"},
    {"plane_lathe",
     "the lathe plane (G18), after milling in X Y or peripheral milling in X Z C, and for arcs "
     "about Y"},
    {"polar_on",
     "polar interpolation on (Fanuc G12.1, Haas G112), before face milling with "
     "millturn.polar_interpolation, after C0; plane_face follows when the machine has it"},
    {"polar_off", "polar interpolation off (Fanuc G13.1, Haas G113), after the face milling"},
    {"plane_side",
     "the plane across the part (G19, Y Z), for arcs of peripheral milling (a radial tool, "
     "millturn.y_axis); without Y, before a radial tool's X Z C moves (no G1 depends on it: it "
     "marks the peripheral work, which plot draws unrolled)"},
    {"clamp_on", "CLAMP/ON (a spindle or axis clamp); without it CLAMP is a warning and a comment"},
    {"clamp_off", "CLAMP/OFF"},
};

const NameSpec kFormats[] = {
    {"default", "every address without a format of its own"},
    {"X", "X words: the radial coordinate (a diameter with output.diameter), cycle X words"},
    {"Z", "Z words: the axial coordinate, cycle Z words"},
    {"I", "arc centre along X (incremental, a radius); the X lead word (Siemens); Haas G76 taper"},
    {"K", "arc centre along Z; the lead word K (LinuxCNC, Siemens); Haas G76 and G31 K"},
    {"F", "feed, and the lead word F"},
    {"S", "spindle speed, surface speed and speed limit"},
    {"R", "Fanuc G76 / G92 taper"},
    {"D", "Haas G76 first cut"},
    {"E", "threads per inch (threading.tpi_address E)"},
    {"Q", "start angle word Q"},
    {"SF=", "SINUMERIK start angle word"},
    {"U", "HEIDENHAIN G31 thread depth"},
    {"A", "HEIDENHAIN G31 infeed angle"},
    {"B", "HEIDENHAIN G31 run-in"},
    {"P", "HEIDENHAIN G31 run-out"},
    {"dwell", "the dwell template's {seconds} and {revolutions}"},
    {"thread_angle",
     "G32 / G92 / Haas G76 Q start angle (Fanuc: 0.001 degree, decimals 0, scale 1000)"},
    {"g76_depth", "G76 depths (Fanuc P/Q in 0.001 mm; LinuxCNC I, J, K)"},
    {"g76_depth_in", "Fanuc G76 depths of an inch program (0.0001 in)"},
    {"g76_allowance", "Fanuc G76 finishing allowance R"},
    {"g76_lead", "LinuxCNC G76 P (lead)"},
    {"g76_angle", "LinuxCNC G76 Q (compound angle)"},
    {"g76_taper", "LinuxCNC G76 E (taper length)"},
    {"cycle99_depth", "CYCLE99 APP, ROP, TDEP, FAL, VRT"},
    {"cycle99_angle", "CYCLE99 IANG, NSP"},
    {"cycle99_lead", "CYCLE99 PIT"},
    {"C", "HEIDENHAIN G31 start angle; the C axis angle (template c_index), degrees"},
    {"hole_peck", "peck depth of the hole templates (Fanuc Q: 0.001 mm, decimals 0, scale 1000)"},
};

// The program's templates before the controls' own, and after them: the holes' and the CL
// words'.
constexpr const TemplateSpec* kCommonTemplates[] = {
    &tmpl::kProgramStart, &tmpl::kProgramEnd,  &tmpl::kToolChange, &tmpl::kSpindleRpm,
    &tmpl::kSpindleCss,   &tmpl::kSpindleStop, &tmpl::kDwell};
constexpr const TemplateSpec* kLaterTemplates[] = {&tmpl::kHoleDrill,
                                                   &tmpl::kHoleDwell,
                                                   &tmpl::kHolePeck,
                                                   &tmpl::kHoleChipBreak,
                                                   &tmpl::kHoleTap,
                                                   &tmpl::kHoleTapRigid,
                                                   &tmpl::kHoleLiveTap,
                                                   &tmpl::kHoleLiveTapLeft,
                                                   &tmpl::kHoleBore,
                                                   &tmpl::kHoleRadialDrill,
                                                   &tmpl::kHoleRadialDwell,
                                                   &tmpl::kHoleRadialPeck,
                                                   &tmpl::kHoleRadialChipBreak,
                                                   &tmpl::kHoleRadialBore,
                                                   &tmpl::kHoleRadialTap,
                                                   &tmpl::kHoleRadialTapLeft,
                                                   &tmpl::kHome,
                                                   &tmpl::kToolChangePosition,
                                                   &tmpl::kAuxfun,
                                                   &tmpl::kPrefun,
                                                   &tmpl::kSelctl,
                                                   &tmpl::kProgramHeader,
                                                   &tmpl::kLiveSpindleRpm,
                                                   &tmpl::kLiveSpindleStop,
                                                   &tmpl::kCIndex};

template <typename T, typename N>
const T* find_by(std::span<const T> list, std::string_view name, N T::*field) {
  auto it = std::find_if(list.begin(), list.end(), [&](const T& t) { return t.*field == name; });
  return it == list.end() ? nullptr : &*it;
}

std::string number_text(double v) {
  return fmt::format("{}", v);
}

// `earlier`, then each control's (`of`), then `later`.
template <typename T, typename Of>
std::vector<T> joined(std::span<const T> earlier, ControlSet controls, Of of,
                      std::span<const T> later) {
  std::vector<T> all(earlier.begin(), earlier.end());
  for (const Control* c : controls) {
    const auto own = of(*c);
    all.insert(all.end(), own.begin(), own.end());
  }
  all.insert(all.end(), later.begin(), later.end());
  return all;
}

}  // namespace

Schema schema(ControlSet controls) {
  Schema s;
  s.cycles.push_back({"none"});
  for (const Control* c : controls) s.cycles.push_back({c->cycle});
  s.loops.push_back({"g33"});
  for (const Control* c : controls)
    for (const LoopBlock& l : c->loops) s.loops.push_back({l.name});
  s.keys = joined<KeySpec>(
      kEarlierKeys, controls, [](const Control& c) { return c.keys; }, kLaterKeys);
  for (KeySpec& k : s.keys) {
    if (std::holds_alternative<const Control * Machine::*>(k.member)) k.choices = s.cycles;
    if (std::holds_alternative<const LoopBlock * Machine::*>(k.member)) k.choices = s.loops;
    if (ControlSlot* slot = std::get_if<ControlSlot>(&k.member)) {
      slot->index = static_cast<uint32_t>(s.control_defaults.size());
      s.control_defaults.push_back(slot->initial);
    }
  }
  s.codes = joined<NameSpec>(
      kEarlierCodes, controls, [](const Control& c) { return c.codes; }, kLaterCodes);
  s.formats = joined<NameSpec>(kFormats, controls, [](const Control& c) { return c.formats; }, {});
  s.templates = joined<const TemplateSpec*>(
      kCommonTemplates, controls, [](const Control& c) { return c.templates; }, kLaterTemplates);
  return s;
}

std::string text_list(const std::vector<std::string>& items) {
  std::string s = "[";
  for (const std::string& i : items) s += (s.size() > 1 ? ", " : "") + json_string(i);
  return s + "]";
}

std::span<const FormatKeySpec> format_keys() {
  return kFormatKeys;
}

const KeySpec* find_key(const Schema& s, std::string_view path) {
  return find_by<KeySpec>(s.keys, path, &KeySpec::path);
}
const FormatKeySpec* find_format_key(std::string_view name) {
  return find_by(format_keys(), name, &FormatKeySpec::name);
}
const NameSpec* find_code(const Schema& s, std::string_view name) {
  return find_by<NameSpec>(s.codes, name, &NameSpec::name);
}
const NameSpec* find_format(const Schema& s, std::string_view name) {
  return find_by<NameSpec>(s.formats, name, &NameSpec::name);
}
const TemplateSpec* find_template(const Schema& s, std::string_view name) {
  for (const TemplateSpec* t : s.templates)
    if (t->name == name) return t;
  return nullptr;
}

bool declared_code(ControlSet controls, std::string_view name) {
  const auto named = [&](std::span<const NameSpec> codes) {
    return find_by(codes, name, &NameSpec::name) != nullptr;
  };
  if (named(kEarlierCodes) || named(kLaterCodes)) return true;
  for (const Control* c : controls)
    if (named(c->codes)) return true;
  return false;
}

bool template_required(const Schema& s, const TemplateSpec& spec, const Machine& m) {
  if (spec.need == Need::kAlways) return true;
  if (spec.need != Need::kSetting) return false;
  const KeySpec* k = find_key(s, spec.setting);
  return k != nullptr && key_value_text(*k, m) == spec.choice;
}

namespace {

// Key `k`'s value `v` (a Machine member) as a machine file writes it.
template <typename V>
std::string member_text(const KeySpec& k, const V& v) {
  if constexpr (std::is_same_v<V, std::vector<std::string>>) {
    return text_list(v);
  } else if constexpr (std::is_same_v<V, std::string>) {
    if (k.type != KeyType::kChoice) return v;
    for (const Choice& c : k.choices)
      if (c.stored == v) return std::string(c.name);
    return v;
  } else if constexpr (std::is_same_v<V, bool>) {
    if (k.type == KeyType::kChoice) return std::string(k.choices[v ? 1 : 0].name);
    return v ? "true" : "false";
  } else if constexpr (std::is_same_v<V, double>) {
    return number_text(v);
  } else if constexpr (std::is_same_v<V, int>) {
    return fmt::format("{}", v);
  } else if constexpr (std::is_same_v<V, const Control*>) {
    return std::string(v != nullptr ? v->cycle : "none");
  } else if constexpr (std::is_same_v<V, const LoopBlock*>) {
    return std::string(v != nullptr ? v->name : "g33");
  } else if constexpr (std::is_same_v<V, LengthOrAuto>) {
    return v.automatic ? std::string("auto") : number_text(v.value);
  } else {  // an enum: the choice of its index
    const size_t i = static_cast<size_t>(v);
    return i < k.choices.size() ? std::string(k.choices[i].name) : std::string("?");
  }
}

}  // namespace

std::string key_value_text(const KeySpec& k, const Machine& m) {
  return std::visit(
      [&](auto member) -> std::string {
        if constexpr (std::is_same_v<decltype(member), ControlSlot>)
          return number_text(member.index < m.control_values.size() ? m.control_values[member.index]
                                                                    : member.initial);
        else
          return member_text(k, m.*member);
      },
      k.member);
}

std::string format_key_value_text(const FormatKeySpec& k, const NumberFormat& f) {
  return std::visit(
      [&](auto member) -> std::string {
        const auto& v = f.*member;
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, bool>) return v ? "true" : "false";
        if constexpr (std::is_same_v<V, double>) return number_text(v);
        if constexpr (std::is_same_v<V, int>) return fmt::format("{}", v);
        return {};
      },
      k.member);
}

}  // namespace clpost
