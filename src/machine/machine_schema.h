#pragma once
// The one declared schema of post and machine files: every key with its type, range, choices and
// a one-line doc (its default is the Machine struct's own initializer), every code name, every
// format name and every template with its fields and when it is required. The loader, `--set`,
// the docs table of docs/machines.md (schema_markdown) and `clpost schema` all read this.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "machine/machine.h"

namespace clpost {

// kNumberOrAuto: a number in the range, or the word `auto` (a LengthOrAuto member).
enum class KeyType : uint8_t { kString, kBool, kNumber, kInt, kChoice, kList, kNumberOrAuto };

// One value a choice key may take. `stored` is what a string field holds for it ("\r\n" for
// crlf); enum and bool fields hold the choice's index.
struct Choice {
  std::string_view name;
  std::string_view stored = {};
};

// A key a control declares (Control::keys): a number, kept in Machine::control_values at
// `index`, the slot schema() gives it (the control declares it with 0); `initial` until a file
// sets it.
struct ControlSlot {
  uint32_t index = 0;
  double initial = 0;
};

// Where a key's value lives: a pointer to the member it sets (no setter functions), or a
// control's slot.
using MachineMember =
    std::variant<std::string Machine::*, bool Machine::*, double Machine::*, int Machine::*,
                 std::vector<std::string> Machine::*, ThreadStrategy Machine::*,
                 ThreadFallback Machine::*, const Control * Machine::*,
                 const LoopBlock * Machine::*, ClAxis Machine::*, LengthOrAuto Machine::*,
                 CRotation Machine::*, PolarX Machine::*, ControlSlot>;
using FormatMember =
    std::variant<int NumberFormat::*, bool NumberFormat::*, double NumberFormat::*>;

struct KeySpec {
  std::string_view path;     // dotted: "threading.strategy"
  std::string_view section;  // docs table it is listed in
  KeyType type;
  MachineMember member;
  std::string_view doc;
  double lo = 0, hi = 0;  // kNumber, kInt, kNumberOrAuto: the accepted range, both ends included
  std::span<const Choice> choices = {};
  bool machine_only = false;  // `extends`
};

struct FormatKeySpec {
  std::string_view name;  // "decimals"
  KeyType type;           // kInt, kBool, kNumber
  FormatMember member;
  std::string_view doc;
  double lo = 0, hi = 0;
  // A default that is no value (`inch_decimals`: the loader's rule): shown in the docs as this,
  // and left out of the JSON schema.
  std::string_view default_text = {};
};

struct NameSpec {  // a code or a format
  std::string_view name;
  std::string_view doc;
  bool required = false;  // codes only: every machine must define it
};

enum class FieldKind : uint8_t { kWhole, kText };

struct TemplateField {
  std::string_view name;
  FieldKind kind;
  std::string_view doc;
};

// When a template must be defined.
enum class Need : uint8_t {
  kAlways,   // every program reaches it: required when the machine loads
  kSetting,  // `setting` = `choice` selects it: required then
  kClWord,   // only some CL words reach it (`cl_words`): an error at that CL line when absent
  kOptional  // used when present, another output otherwise
};

struct TemplateSpec {
  std::string_view name;
  std::span<const TemplateField> fields;
  Need need;
  std::string_view doc;
  std::string_view setting = {};   // kSetting: the key ("threading.cycle") …
  std::string_view choice = {};    // … and its value ("fanuc_g76")
  std::string_view cl_words = {};  // kClWord / kOptional: what reaches it ("SPINDL/…,SMM")
  // The field named `f`, at compile time: a name the template does not declare does not compile.
  consteval size_t field(std::string_view f, FieldKind kind) const {
    for (size_t i = 0; i < fields.size(); ++i)
      if (fields[i].name == f) {
        if (fields[i].kind != kind) throw "field kind mismatch";
        return i;
      }
    throw "not a field of this template";
  }
};

// --- Templates -------------------------------------------------------------------------------
// Declared here, in the header, so that TemplateFill (template_values.h) checks field names at
// compile time.
namespace tmpl {

using enum FieldKind;

inline constexpr TemplateField kProgramStartFields[] = {
    {"program_number", kWhole, "output.program_number"},
    {"program_name", kText, "the PARTNO text"},
    {"units_code", kText, "codes.metric or codes.inch, as the CL's units"},
    {"machine", kText, "the machine's name"},
    {"file", kText, "the CL file"}};
inline constexpr TemplateField kProgramEndFields[] = {
    {"program_number", kWhole, "output.program_number"},
    {"program_name", kText, "the PARTNO text"}};
inline constexpr TemplateField kToolChangeFields[] = {
    {"tool", kWhole, "tool number"},
    {"offset", kWhole, "offset number (LOADTL ADJUST/OSETNO, else the tool number)"},
    {"tool_name", kText, "tool name (empty)"}};
inline constexpr TemplateField kSpindleRpmFields[] = {
    {"rpm", kText, "speed, format S"},
    {"direction", kText, "codes.spindle_cw or spindle_ccw"},
    {"max_rpm", kText,
     "the machine's speed limit (limits.max_rpm; without one, the speed), format S: where a "
     "limit given for constant surface speed also limits a speed (SINUMERIK's LIMS under G97)"}};
inline constexpr TemplateField kSpindleCssFields[] = {
    {"speed", kText, "surface speed, format S"},
    {"max_rpm", kText, "speed limit (MAXRPM, limits.max_rpm), format S"},
    {"direction", kText, "codes.spindle_cw or spindle_ccw"}};
inline constexpr TemplateField kDwellFields[] = {
    {"seconds", kText, "dwell time, format dwell"},
    {"revolutions", kText, "dwell in spindle revolutions, format dwell"}};

inline constexpr TemplateField kHoleFields[] = {
    {"x", kText, "hole X (0: on the centre line), format X"},
    {"z", kText, "hole bottom Z, format Z"},
    {"top", kText, "hole top Z (the CL hole point), format Z"},
    {"r", kText, "R plane Z (top plus the clearance), format Z"},
    {"r_inc", kText, "R plane relative to the start Z, format Z"},
    {"start", kText, "start Z: where the tool is before the cycle and returns to, format Z"},
    {"safety", kText, "R plane distance from the top (the clearance), format Z"},
    {"depth", kText, "hole depth below the top, format Z"},
    {"peck", kText, "peck depth, format hole_peck"},
    {"dwell", kText, "dwell at the bottom in seconds, format dwell"},
    {"dwell_ms", kWhole, "dwell at the bottom in milliseconds"},
    {"feed", kText, "feed, format F (a tap: its lead per revolution)"},
    {"feed_mode", kText, "codes.feed_per_rev or feed_per_min, as the feed"},
    {"lead", kText, "tap lead per revolution, format F"},
    {"rpm", kText, "spindle speed, format S"}};

// A radial hole of a live tool (docs/millturn.md): drilled along X toward the centre line at Z,
// C written before it (c_index).
inline constexpr TemplateField kRadialHoleFields[] = {
    {"x", kText, "hole bottom X (the depth along X), format X, a diameter where X is one"},
    {"z", kText, "hole Z, format Z"},
    {"top", kText, "hole top X (the CL hole point), format X"},
    {"r", kText, "R plane X (top plus the clearance), format X"},
    {"r_radius", kText,
     "R plane X as a radius, format X (LinuxCNC's G19 R: rs274 reads it so in G7)"},
    {"r_inc", kText, "R plane relative to the start X, a radius, format X (Fanuc G87's R)"},
    {"start", kText, "start X: where the tool is before the cycle and returns to, format X"},
    {"safety", kText, "R plane distance from the top (the clearance), format X, a radius"},
    {"depth", kText, "hole depth below the top, format X, a radius"},
    {"peck", kText, "peck depth, format hole_peck"},
    {"dwell", kText, "dwell at the bottom in seconds, format dwell"},
    {"dwell_ms", kWhole, "dwell at the bottom in milliseconds"},
    {"feed", kText, "feed, format F"},
    {"feed_mode", kText, "codes.feed_per_rev or feed_per_min, as the feed"},
    {"lead", kText, "tap lead per revolution, format F"},
    {"rpm", kText, "live tool speed, format S"}};

inline constexpr TemplateField kLiveSpindleFields[] = {
    {"rpm", kText, "live tool speed, format S"},
    {"direction", kText, "codes.live_spindle_cw or live_spindle_ccw"}};
inline constexpr TemplateField kCIndexFields[] = {{"c", kText, "C angle, degrees, format C"},
                                                  {"address", kText, "millturn.c_address"}};

inline constexpr TemplateField kHeaderFields[] = {
    {"text", kText, "one line of the tool list or the cycle time, as comment text"}};
inline constexpr TemplateField kCodeFields[] = {
    {"code", kWhole, "the number the CL gave (AUXFUN/8: 8)"}};

using enum Need;

inline constexpr TemplateSpec kProgramStart{"program_start", kProgramStartFields, kAlways,
                                            "the program's first blocks"};
inline constexpr TemplateSpec kProgramEnd{"program_end", kProgramEndFields, kAlways,
                                          "the program's last blocks"};
inline constexpr TemplateSpec kToolChange{"tool_change", kToolChangeFields, kAlways, "LOADTL"};
inline constexpr TemplateSpec kSpindleRpm{"spindle_rpm", kSpindleRpmFields, kAlways,
                                          "SPINDL/n,RPM; a thread under constant surface speed"};
inline constexpr TemplateSpec kSpindleCss{
    "spindle_css",        kSpindleCssFields, kClWord, "constant surface speed", {}, {},
    "SPINDL/…,SMM or SFM"};
inline constexpr TemplateSpec kSpindleStop{"spindle_stop", {}, kAlways, "SPINDL/OFF"};
inline constexpr TemplateSpec kDwell{
    "dwell",
    kDwellFields,
    kClWord,
    "a dwell; may ask for {seconds} or {revolutions} (converted through the spindle's RPM)",
    {},
    {},
    "DELAY/t or DELAY/REV,n"};

inline constexpr TemplateSpec kHoleDrill{
    "hole_drill",
    kHoleFields,
    kOptional,
    "drilling to depth, rapid out (G81); without it G0/G1 moves",
    {},
    {},
    "CYCLE/DRILL, REAM without DWELL"};
inline constexpr TemplateSpec kHoleDwell{
    "hole_dwell",
    kHoleFields,
    kOptional,
    "drilling with a dwell at the bottom (G82); without it G0/G1/G4 moves",
    {},
    {},
    "CYCLE/DRILL,…,DWELL,t"};
inline constexpr TemplateSpec kHolePeck{
    "hole_peck",
    kHoleFields,
    kOptional,
    "peck drilling, full retract after each peck (G83); without it G0/G1 moves",
    {},
    {},
    "CYCLE/DEEP, DEEP2"};
inline constexpr TemplateSpec kHoleChipBreak{
    "hole_chip_break",
    kHoleFields,
    kOptional,
    "chip-breaking peck drilling, short retract (G73); without it G0/G1 moves",
    {},
    {},
    "CYCLE/BRKCHP"};
inline constexpr TemplateSpec kHoleTap{
    "hole_tap",
    kHoleFields,
    kOptional,
    "tapping with a floating holder (G84); without it G1 moves with the spindle reversed",
    {},
    {},
    "CYCLE/TAP"};
inline constexpr TemplateSpec kHoleTapRigid{
    "hole_tap_rigid",
    kHoleFields,
    kOptional,
    "rigid tapping (M29 G84, G33.1), used when holes.rigid_tapping; else hole_tap",
    {},
    {},
    "CYCLE/TAP"};
// A tap of a live tool (docs/millturn.md): synchronised with the live spindle, never with the
// main one, so there is no moves fallback (a machine without it refuses the tap).
inline constexpr TemplateSpec kHoleLiveTap{
    "hole_live_tap",
    kHoleFields,
    kOptional,
    "face tapping of a live tool at X with C, synchronised with the live spindle (Haas G95, "
    "Fanuc M29 G84, LinuxCNC G33.1 $1); without it a live tool's tap is an error",
    {},
    {},
    "CYCLE/TAP with a live tool, tool axis along Z"};
inline constexpr TemplateSpec kHoleLiveTapLeft{
    "hole_live_tap_left",
    kHoleFields,
    kOptional,
    "left-hand face tapping of a live tool (the live spindle counter-clockwise: Haas G186, "
    "LinuxCNC G33.1 $1 after M4 $1); without it a live tool's left-hand tap is an error",
    {},
    {},
    "CYCLE/TAP with a live tool turning CCLW, tool axis along Z"};
inline constexpr TemplateSpec kHoleBore{
    "hole_bore",
    kHoleFields,
    kOptional,
    "boring or reaming, feed in and feed out (G85); without it G1 moves",
    {},
    {},
    "CYCLE/BORE, REAM"};

inline constexpr TemplateSpec kHoleRadialDrill{
    "hole_radial_drill",
    kRadialHoleFields,
    kOptional,
    "radial drilling of a live tool along X at C (G19 G81, Haas G241, Fanuc G87); without it G0/G1 "
    "moves",
    {},
    {},
    "CYCLE/DRILL, REAM without DWELL, tool axis through the centre line"};
inline constexpr TemplateSpec kHoleRadialDwell{
    "hole_radial_dwell",
    kRadialHoleFields,
    kOptional,
    "radial drilling with a dwell at the bottom (G19 G82, Haas G242, Fanuc G87 P); without it "
    "G0/G1/G4 moves",
    {},
    {},
    "CYCLE/DRILL,…,DWELL,t, tool axis through the centre line"};
inline constexpr TemplateSpec kHoleRadialPeck{
    "hole_radial_peck",
    kRadialHoleFields,
    kOptional,
    "radial peck drilling, full retract (G19 G83, Haas G243, Fanuc G87 Q); without it G0/G1 moves",
    {},
    {},
    "CYCLE/DEEP, DEEP2, tool axis through the centre line"};
inline constexpr TemplateSpec kHoleRadialChipBreak{
    "hole_radial_chip_break",
    kRadialHoleFields,
    kOptional,
    "radial chip-breaking peck drilling (G19 G73); without it G0/G1 moves",
    {},
    {},
    "CYCLE/BRKCHP, tool axis through the centre line"};
inline constexpr TemplateSpec kHoleRadialBore{
    "hole_radial_bore",
    kRadialHoleFields,
    kOptional,
    "radial boring or reaming, feed in and out (G19 G85); without it G1 moves",
    {},
    {},
    "CYCLE/BORE, REAM, tool axis through the centre line"};

inline constexpr TemplateSpec kHoleRadialTap{
    "hole_radial_tap",
    kRadialHoleFields,
    kOptional,
    "radial tapping of a live tool along X at C, synchronised with the live spindle (Haas G195, "
    "Fanuc M29 G88, LinuxCNC G33.1 $1); without it a live tool's radial tap is an error",
    {},
    {},
    "CYCLE/TAP with a live tool, tool axis through the centre line"};
inline constexpr TemplateSpec kHoleRadialTapLeft{
    "hole_radial_tap_left",
    kRadialHoleFields,
    kOptional,
    "left-hand radial tapping of a live tool (the live spindle counter-clockwise: Haas G196, "
    "LinuxCNC G33.1 $1 after M4 $1); without it a live tool's left-hand radial tap is an error",
    {},
    {},
    "CYCLE/TAP with a live tool turning CCLW, tool axis through the centre line"};

inline constexpr TemplateSpec kLiveSpindleRpm{
    "live_spindle_rpm",
    kLiveSpindleFields,
    kSetting,
    "the live (driven) tool's speed and direction (`M133 P{rpm}`, LinuxCNC `{direction} $1 "
    "S{rpm}`): SPINDL/n,RPM while a milling tool is loaded",
    "millturn.live_tools",
    "true",
    "SPINDL/ after a milling tool's LOADTL"};
inline constexpr TemplateSpec kLiveSpindleStop{"live_spindle_stop",
                                               {},
                                               kSetting,
                                               "the live tool stops (`M135`, LinuxCNC `M5 $1`)",
                                               "millturn.live_tools",
                                               "true",
                                               "SPINDL/OFF with a milling tool; a tool change"};
inline constexpr TemplateSpec kCIndex{"c_index",
                                      kCIndexFields,
                                      kSetting,
                                      "positions the C axis (`G0 {address}{c}`)",
                                      "millturn.c_axis",
                                      "true",
                                      "ROTABL/a,…,CAXIS, ROTATE/CAXIS,…"};

inline constexpr TemplateSpec kProgramHeader{
    "program_header",
    kHeaderFields,
    kOptional,
    "the program and machine names, the tool list and the estimated cycle time after the "
    "program start, the template once per line (`({text})`); the program then waits in an "
    "unnamed temporary file (beside the output file) until its end",
    {},
    {},
    "any program"};
inline constexpr TemplateSpec kHome{
    "home",
    {},
    kOptional,
    "the machine's home return, one line per axis in the order it moves them (`G28 U0.`, `G28 "
    "W0.`); without it GOHOME/x,y,z is a rapid move there, GOHOME alone a warning",
    {},
    {},
    "GOHOME"};
inline constexpr TemplateSpec kToolChangePosition{
    "tool_change_position",
    {},
    kOptional,
    "where the turret goes before every tool change (a home return or a safe position); "
    "without it the tool changes where it is",
    {},
    {},
    "LOADTL"};
inline constexpr TemplateSpec kAuxfun{
    "auxfun",  kCodeFields,
    kOptional, "an M code the CL asks for; without it AUXFUN is a warning and a comment",
    {},        {},
    "AUXFUN/n"};
inline constexpr TemplateSpec kPrefun{
    "prefun",  kCodeFields,
    kOptional, "a G code the CL asks for; without it PREFUN is a warning and a comment",
    {},        {},
    "PREFUN/n"};
inline constexpr TemplateSpec kSelctl{
    "selctl",
    kCodeFields,
    kOptional,
    "SELCTL/n: select control n (a channel or turret); without it a warning and a comment",
    {},
    {},
    "SELCTL/n"};

}  // namespace tmpl

// --- The whole schema ------------------------------------------------------------------------

// The schema of the post and machine files a program reads, for the set of controls it was given
// (machine/control.h): the program's own keys, codes, formats and templates with each control's
// (Control::keys, codes, formats, templates) among them, in the set's order. threading.cycle's
// choices are "none" and the set's cycles, threading.loop's "g33" and the set's loop blocks. Its
// keys' choices point into it: it moves, never copies.
struct Schema {
  std::vector<KeySpec> keys;
  std::vector<NameSpec> codes;
  std::vector<NameSpec> formats;
  std::vector<const TemplateSpec*> templates;
  std::vector<Choice> cycles;            // threading.cycle's
  std::vector<Choice> loops;             // threading.loop's
  std::vector<double> control_defaults;  // each control slot's initial value

  Schema() = default;
  Schema(Schema&&) = default;
  Schema& operator=(Schema&&) = default;
  Schema(const Schema&) = delete;
  Schema& operator=(const Schema&) = delete;
};
Schema schema(ControlSet controls);

// The number format keys (decimals, …): the same for every set of controls.
std::span<const FormatKeySpec> format_keys();

// Lookups: nullptr when the name is not declared.
const KeySpec* find_key(const Schema& s, std::string_view path);
const FormatKeySpec* find_format_key(std::string_view name);
const NameSpec* find_code(const Schema& s, std::string_view name);
const NameSpec* find_format(const Schema& s, std::string_view name);
const TemplateSpec* find_template(const Schema& s, std::string_view name);
// Whether code `name` is the program's or one of `controls`' (schema(controls) has it), without
// building the schema.
bool declared_code(ControlSet controls, std::string_view name);

// Whether `spec` is required on machine `m` (always, or selected by m's settings).
bool template_required(const Schema& s, const TemplateSpec& spec, const Machine& m);

// Key `k`'s value in `m` as a machine file would write it ("cycle", "0.005", "[\"%\", \"O\"]").
std::string key_value_text(const KeySpec& k, const Machine& m);
// A list of text as a flow sequence of JSON strings: ["%", "O"].
std::string text_list(const std::vector<std::string>& items);
// A format key's value as written.
std::string format_key_value_text(const FormatKeySpec& k, const NumberFormat& f);

}  // namespace clpost
