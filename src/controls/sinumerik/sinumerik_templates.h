#pragma once
// SINUMERIK's templates: the thread cycle CYCLE99, the chain cycle CYCLE98 and the
// undercut CYCLE96, declared
// with their fields (machine/machine_schema.h: a field name a template does not declare does not
// compile). Listed in the schema by its Control (Control::templates).
#include "machine/machine_schema.h"

namespace clpost::tmpl {

using enum FieldKind;
using enum Need;

inline constexpr TemplateField kCycle99Fields[] = {
    {"spl", kText, "thread start Z"},
    {"dm1", kText, "diameter at the start"},
    {"fpl", kText, "thread end Z"},
    {"dm2", kText, "diameter at the end"},
    {"app", kText, "run-in (threading.run_in, or δ1 with auto), format cycle99_depth"},
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
    {"app", kText, "run-in (δ1 with threading.run_in auto, else 0), format cycle99_depth"},
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

}  // namespace clpost::tmpl
