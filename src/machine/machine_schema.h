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

enum class KeyType : uint8_t { kString, kBool, kNumber, kInt, kChoice, kList };

// One value a choice key may take. `stored` is what a string field holds for it ("\r\n" for
// crlf); enum and bool fields hold the choice's index.
struct Choice {
  std::string_view name;
  std::string_view stored = {};
};

// Where a key's value lives: a pointer to the member it sets (no setter functions).
using MachineMember =
    std::variant<std::string Machine::*, bool Machine::*, double Machine::*, int Machine::*,
                 std::vector<std::string> Machine::*, ThreadStrategy Machine::*,
                 ThreadFallback Machine::*, ThreadCycle Machine::*, ThreadLoop Machine::*,
                 ClAxis Machine::*>;
using FormatMember =
    std::variant<int NumberFormat::*, bool NumberFormat::*, double NumberFormat::*>;

struct KeySpec {
  std::string_view path;     // dotted: "threading.strategy"
  std::string_view section;  // docs table it is listed in
  KeyType type;
  MachineMember member;
  std::string_view doc;
  double lo = 0, hi = 0;  // kNumber, kInt: the accepted range, both ends included
  std::span<const Choice> choices = {};
  bool machine_only = false;  // `extends`
};

struct FormatKeySpec {
  std::string_view name;  // "decimals"
  KeyType type;           // kInt, kBool, kNumber
  FormatMember member;
  std::string_view doc;
  double lo = 0, hi = 0;
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
    {"rpm", kText, "speed, format S"}, {"direction", kText, "codes.spindle_cw or spindle_ccw"}};
inline constexpr TemplateField kSpindleCssFields[] = {
    {"speed", kText, "surface speed, format S"},
    {"max_rpm", kText, "speed limit (MAXRPM, limits.max_rpm), format S"},
    {"direction", kText, "codes.spindle_cw or spindle_ccw"}};
inline constexpr TemplateField kDwellFields[] = {
    {"seconds", kText, "dwell time, format dwell"},
    {"revolutions", kText, "dwell in spindle revolutions, format dwell"}};
inline constexpr TemplateField kCycle99Fields[] = {
    {"spl", kText, "thread start Z"},
    {"dm1", kText, "diameter at the start"},
    {"fpl", kText, "thread end Z"},
    {"dm2", kText, "diameter at the end"},
    {"app", kText, "run-in (threading.run_in), format cycle99_depth"},
    {"rop", kText, "run-out, format cycle99_depth"},
    {"tdep", kText, "thread depth, format cycle99_depth"},
    {"fal", kText, "finishing allowance, format cycle99_depth"},
    {"iang", kText, "infeed angle, format cycle99_angle"},
    {"nsp", kText, "start angle offset, format cycle99_angle"},
    {"nrc", kText, "number of roughing cuts"},
    {"nid", kText, "number of idle (spring) passes"},
    {"pit", kText, "lead, format cycle99_lead"},
    {"vari", kText, "machining type (infeed law and flank)"},
    {"numth", kText, "number of starts"},
    {"vrt", kText, "retraction, format cycle99_depth"},
    {"pita", kText, "lead unit"},
    {"psys", kText, "thread type"}};
inline constexpr TemplateField kCycle98Fields[] = {
    {"po1", kText, "contour point 1 Z"},
    {"dm1", kText, "diameter at point 1"},
    {"po2", kText, "contour point 2 Z"},
    {"dm2", kText, "diameter at point 2"},
    {"po3", kText, "contour point 3 Z (point 2 again for one segment)"},
    {"dm3", kText, "diameter at point 3"},
    {"po4", kText, "contour point 4 Z (the last point again for fewer segments)"},
    {"dm4", kText, "diameter at point 4"},
    {"app", kText, "run-in, format cycle99_depth"},
    {"rop", kText, "run-out, format cycle99_depth"},
    {"tdep", kText, "thread depth, format cycle99_depth"},
    {"fal", kText, "finishing allowance, format cycle99_depth"},
    {"iang", kText, "infeed angle, format cycle99_angle"},
    {"nsp", kText, "start angle offset, format cycle99_angle"},
    {"nrc", kText, "number of roughing cuts"},
    {"nid", kText, "number of idle (spring) passes"},
    {"pp1", kText, "lead of segment 1, format cycle99_lead"},
    {"pp2", kText, "lead of segment 2 (= PP1), format cycle99_lead"},
    {"pp3", kText, "lead of segment 3 (= PP1), format cycle99_lead"},
    {"vari", kText, "machining type 1 to 4 (infeed law, external or internal)"},
    {"numth", kText, "number of starts"},
    {"vrt", kText, "retraction, format cycle99_depth"}};
inline constexpr TemplateField kCycle96Fields[] = {{"diath", kText, "nominal diameter, format X"},
                                                   {"axsa", kText, "undercut position Z, format Z"},
                                                   {"form", kText, "DIN 76 form A, B, C or D"}};
inline constexpr TemplateField kFanucG76Fields[] = {
    {"m", kText, "finishing passes, two digits"},
    {"chamfer", kText, "chamfer in 0.1 leads, two digits"},
    {"angle", kText, "tool angle, two digits"},
    {"min_cut", kText, "minimum cut, format g76_depth (g76_depth_in in inches)"},
    {"allowance", kText, "finishing allowance, format g76_allowance"},
    {"x", kText, "thread end X"},
    {"z", kText, "thread end Z"},
    {"taper", kText, "' R' and the taper, or empty"},
    {"height", kText, "thread height, format g76_depth"},
    {"first_cut", kText, "first cut depth, format g76_depth"},
    {"lead", kText, "lead, format F"}};
inline constexpr TemplateField kHaasG76Fields[] = {
    {"x", kText, "thread end X"},
    {"z", kText, "thread end Z"},
    {"taper", kText, "' I' and the taper, or empty"},
    {"height", kText, "thread height, format K"},
    {"first_cut", kText, "first cut depth, format D"},
    {"angle", kText, "tool angle"},
    {"mode", kText, "infeed mode P"},
    {"start_angle", kText, "' Q' and the start angle (format thread_angle), or empty"},
    {"lead", kText, "lead, format F"}};
inline constexpr TemplateField kG92Fields[] = {
    {"x", kText, "pass X"},
    {"z", kText, "thread end Z (g92_next: ' Z' and Z when it changed, else empty)"},
    {"taper", kText, "' R' and the taper, or empty"},
    {"lead", kText, "lead, format F (empty in g92_next)"},
    {"start_angle", kText, "' Q' and the start angle (format thread_angle), or empty"}};
inline constexpr TemplateField kLinuxcncG76Fields[] = {
    {"p", kText, "lead, format g76_lead"},
    {"z", kText, "thread end Z"},
    {"i", kText, "thread peak offset, format g76_depth"},
    {"j", kText, "first cut depth, format g76_depth"},
    {"k", kText, "full thread depth, format g76_depth"},
    {"r", kText, "depth degression"},
    {"q", kText, "compound angle, format g76_angle"},
    {"h", kText, "spring passes"},
    {"e", kText, "taper length, format g76_taper"},
    {"l", kText, "taper ends (0 none, 2 exit)"}};
inline constexpr TemplateField kHeidenhainG31Fields[] = {
    {"f", kText, "lead, format F"},
    {"u", kText, "thread depth, format U"},
    {"ic", kText, "number of cuts"},
    {"v", kText, "infeed type"},
    {"h", kText, "flank offset type (codes g31_h_*)"},
    {"a", kText, "infeed angle, format A"},
    {"d", kText, "number of starts"},
    {"q", kText, "idle (spring) passes"},
    {"c", kText, "start angle, format C"},
    {"bd", kText, "run-in/run-out direction"},
    {"b", kText, "run-in length, format B"},
    {"p", kText, "run-out length, format P"},
    {"k", kText, "thread run-out, format K"},
    {"x1", kText, "contour start X"},
    {"z1", kText, "contour start Z"},
    {"x2", kText, "contour end X"},
    {"z2", kText, "contour end Z"}};

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
inline constexpr TemplateSpec kCycle99{
    "cycle99", kCycle99Fields, kSetting, "SINUMERIK thread cycle", "threading.cycle", "cycle99"};
inline constexpr TemplateSpec kCycle98{"cycle98",
                                       kCycle98Fields,
                                       kOptional,
                                       "SINUMERIK chained thread of 1 to 3 segments; without it a "
                                       "chain is cut with the G33 loop",
                                       {},
                                       {},
                                       "THREAD/ON,...,CHAIN"};
inline constexpr TemplateSpec kCycle96{"cycle96",
                                       kCycle96Fields,
                                       kOptional,
                                       "SINUMERIK thread undercut; without it the undercut is "
                                       "cut with G0/G1 moves",
                                       {},
                                       {},
                                       "CYCLE/UNDCUT"};
inline constexpr TemplateSpec kFanucG76{"fanuc_g76",           kFanucG76Fields,   kSetting,
                                        "Fanuc two-block G76", "threading.cycle", "fanuc_g76"};
inline constexpr TemplateSpec kHaasG76{"haas_g76",           kHaasG76Fields,    kSetting,
                                       "Haas one-block G76", "threading.cycle", "haas_g76"};
inline constexpr TemplateSpec kG92{
    "g92", kG92Fields, kSetting, "first G92 block of a thread", "threading.loop", "g92"};
inline constexpr TemplateSpec kG92Next{
    "g92_next", kG92Fields, kSetting, "next passes while G92 is modal", "threading.loop", "g92"};
inline constexpr TemplateSpec kLinuxcncG76{"linuxcnc_g76", kLinuxcncG76Fields, kSetting,
                                           "LinuxCNC G76", "threading.cycle",  "linuxcnc_g76"};
inline constexpr TemplateSpec kLinuxcncG76Taper{
    "linuxcnc_g76_taper", kLinuxcncG76Fields, kSetting, "LinuxCNC G76 with an exit taper (E, L)",
    "threading.cycle",    "linuxcnc_g76"};
inline constexpr TemplateSpec kHeidenhainG31{
    "heidenhain_g31",  kHeidenhainG31Fields, kSetting, "HEIDENHAIN G31 with its contour and G80",
    "threading.cycle", "heidenhain_g31"};

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
inline constexpr TemplateSpec kHoleBore{
    "hole_bore",
    kHoleFields,
    kOptional,
    "boring or reaming, feed in and feed out (G85); without it G1 moves",
    {},
    {},
    "CYCLE/BORE, REAM"};

inline constexpr TemplateSpec kProgramHeader{
    "program_header",
    kHeaderFields,
    kOptional,
    "the tool list and the estimated cycle time after the program start, the template once per "
    "line (`({text})`); the program is then kept in memory until its end",
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

std::span<const KeySpec> machine_keys();
std::span<const FormatKeySpec> format_keys();
std::span<const NameSpec> code_names();
std::span<const NameSpec> format_names();
std::span<const TemplateSpec* const> template_specs();

// Lookups: nullptr when the name is not declared.
const KeySpec* find_key(std::string_view path);
const FormatKeySpec* find_format_key(std::string_view name);
const NameSpec* find_code(std::string_view name);
const NameSpec* find_format(std::string_view name);
const TemplateSpec* find_template(std::string_view name);

// Whether `spec` is required on machine `m` (always, or selected by m's settings).
bool template_required(const TemplateSpec& spec, const Machine& m);

// Key `k`'s value in `m` as a machine file would write it ("cycle", "0.005", "[\"%\", \"O\"]").
std::string key_value_text(const KeySpec& k, const Machine& m);
// A list of text as a flow sequence of JSON strings: ["%", "O"].
std::string text_list(const std::vector<std::string>& items);
// A format key's value as written.
std::string format_key_value_text(const FormatKeySpec& k, const NumberFormat& f);

}  // namespace clpost
