#include "reader/cldata_words.h"

#include <array>

namespace clpost::cldata {

namespace {

struct Entry {
  int64_t code;
  std::string_view name;
};

// Type-2000 majors: 1-22 without parameters, 1001-1072 with them (apt360_notes.txt).
constexpr Entry kMajors[] = {
    {1, "END"},
    {2, "STOP"},
    {3, "OPSTOP"},
    {4, "ISTOP"},
    {5, "RAPID"},
    {6, "SWITCH"},
    {7, "RETRCT"},
    {8, "DRESS"},
    {9, "PICKUP"},
    {10, "UNLOAD"},
    {11, "PENUP"},
    {12, "PENDWN"},
    {13, "ZERO"},
    {14, "GOHOME"},
    {15, "RESET"},
    {16, "GOCLER"},
    {17, "DRAWLI"},
    {18, "PROBY"},
    {19, "PROBX"},
    {20, "ULOCKX"},
    {21, "LOCKX"},
    {22, "FACEML"},
    {1001, "PLUNGE"},
    {1002, "HEAD"},
    {1003, "MODE"},
    {1004, "CLEARP"},
    {1005, "TMARK"},
    {1006, "REWIND"},
    {1007, "CUTCOM"},
    {1008, "REVERS"},
    {1009, "FEDRAT"},
    {1010, "DELAY"},
    {1011, "AIR"},
    {1012, "DELETE"},
    {1013, "LEADER"},
    {1014, "PPLOT"},
    {1015, "MACHIN"},
    {1016, "MCHTOL"},
    {1017, "PIVOTZ"},
    {1018, "MCHFIN"},
    {1019, "SEQNO"},
    {1020, "INTCOD"},
    {1021, "DISPLY"},
    {1022, "AUXFUN"},
    {1023, "CHECK"},
    {1024, "POSTN"},
    {1025, "TOOLNO"},
    {1026, "ROTABL"},
    {1027, "ORIGIN"},
    {1028, "SAFETY"},
    {1029, "ARCSLP"},
    {1030, "COOLNT"},
    {1031, "SPINDL"},
    {1032, "IFRO"},
    {1033, "TURRET"},
    {1035, "ROTHED"},
    {1036, "THREAD"},
    {1037, "TRANS"},
    {1038, "TRACUT"},
    {1039, "INDEX"},
    {1040, "COPY"},
    {1041, "PLOT"},
    {1042, "OVPLOT"},
    {1043, "LETTER"},
    {1044, "PPRINT"},
    {1045, "PARTNO"},
    {1046, "INSERT"},
    {1047, "CAMERA"},
    {1048, "PREFUN"},
    {1049, "COUPLE"},
    {1050, "PITCH"},
    {1051, "MDWRIT"},
    {1052, "MDEND"},
    {1053, "ASLOPE"},
    {1054, "CYCLE"},
    {1055, "LOADTL"},
    {1056, "SELCTL"},
    {1057, "CLRSRF"},
    {1058, "DWELL"},
    {1059, "DRAFT"},
    {1060, "CLAMP"},
    {1061, "PLABEL"},
    {1062, "MAXDPM"},
    {1063, "SLOWDN"},
    {1064, "MAXVEL"},
    {1065, "LPRINT"},
    {1066, "MOVETO"},
    {1067, "CORNFD"},
    {1068, "PBS"},
    {1069, "REGBRK"},
    {1070, "VTLAXS"},
    {1071, "WCORN"},
    {1072, "MAGTAP"},
    // clpost's own codes for majors APT360 did not have.
    {1901, "UNITS"},
    {1902, "OP"},
};

// Minor words (vocabulary class 29 of apt360_notes.txt). Where two words share a code the first
// one listed is the name written.
constexpr Entry kMinors[] = {
    {1, "ATANGL"},
    {2, "CENTER"},
    {3, "CROSS"},
    {4, "FUNOFY"},
    {5, "INTOF"},
    {6, "INVERS"},
    {7, "LARGE"},
    {8, "LEFT"},
    {9, "LENGTH"},
    {10, "MINUS"},
    {11, "NEGX"},
    {12, "NEGY"},
    {13, "NEGZ"},
    {14, "NOX"},
    {15, "NOY"},
    {16, "NOZ"},
    {17, "PARLEL"},
    {18, "PERPTO"},
    {19, "PLUS"},
    {20, "POSX"},
    {21, "POSY"},
    {22, "POSZ"},
    {23, "RADIUS"},
    {24, "RIGHT"},
    {25, "SCALE"},
    {26, "SMALL"},
    {27, "TANTO"},
    {27, "DSTAN"},
    {28, "TIMES"},
    {29, "TRANSL"},
    {30, "UNIT"},
    {31, "XLARGE"},
    {32, "XSMALL"},
    {33, "XYPLAN"},
    {34, "XYROT"},
    {35, "YLARGE"},
    {36, "YSMALL"},
    {37, "YZPLAN"},
    {38, "YZROT"},
    {39, "ZLARGE"},
    {40, "ZSMALL"},
    {41, "ZXPLAN"},
    {42, "ZXROT"},
    {43, "3PT2SL"},
    {44, "4PT1SL"},
    {45, "5PT"},
    {46, "INTERC"},
    {47, "SLOPE"},
    {48, "IN"},
    {49, "OUT"},
    {50, "OPEN"},
    {51, "ALL"},
    {52, "LAST"},
    {53, "NOMORE"},
    {54, "SAME"},
    {55, "MODIFY"},
    {56, "MIRROR"},
    {57, "START"},
    {58, "ENDARC"},
    {59, "CCLW"},
    {60, "CLW"},
    {61, "MEDIUM"},
    {62, "HIGH"},
    {63, "LOW"},
    {64, "CONST"},
    {65, "DECR"},
    {66, "INCR"},
    {67, "PERSP"},
    {68, "ROTREF"},
    {69, "TO"},
    {70, "PAST"},
    {71, "ON"},
    {72, "OFF"},
    {73, "IPM"},
    {74, "IPR"},
    {75, "CIRCUL"},
    {76, "LINEAR"},
    {77, "PARAB"},
    {78, "RPM"},
    {79, "MAXRPM"},
    {80, "TURN"},
    {81, "FACE"},
    {82, "BORE"},
    {83, "BOTH"},
    {84, "XAXIS"},
    {85, "YAXIS"},
    {86, "ZAXIS"},
    {87, "ARC"},
    {88, "AUTO"},
    {89, "FLOOD"},
    {90, "MIST"},
    {91, "TAPKUL"},
    {92, "STEP"},
    {93, "MAIN"},
    {93, "RAIL"},
    {94, "SIDE"},
    {95, "LINCIR"},
    {96, "MAXIPM"},
    {97, "REV"},
    {98, "TYPE"},
    {99, "NIXIE"},
    {100, "LIGHT"},
    {101, "FOURPT"},
    {102, "TWOPT"},
    {103, "PTSLOP"},
    {104, "PTNORM"},
    {105, "SPLINE"},
    {106, "RTHETA"},
    {107, "THETAR"},
    {108, "XYZ"},
    {109, "TANON"},
    {110, "TRFORM"},
    {111, "NORMAL"},
    {112, "UP"},
    {113, "DOWN"},
    {114, "LOCK"},
    {115, "SFM"},
    {116, "XCOORD"},
    {117, "YCOORD"},
    {118, "ZCOORD"},
    {119, "MULTRD"},
    {120, "XYVIEW"},
    {121, "YZVIEW"},
    {122, "ZXVIEW"},
    {123, "SOLID"},
    {124, "DASH"},
    {125, "DOTTED"},
    {126, "CIRLIN"},
    {127, "DITTO"},
    {128, "PEN"},
    {129, "SCRIBE"},
    {130, "BLACK"},
    {131, "RED"},
    {132, "GREEN"},
    {133, "BLUE"},
    {134, "INTENS"},
    {135, "LITE"},
    {136, "MED"},
    {137, "DARK"},
    {138, "CHUCK"},
    {139, "COLLET"},
    {140, "AAXIS"},
    {141, "BAXIS"},
    {142, "CAXIS"},
    {143, "TPI"},
    {144, "OPTION"},
    {145, "RANGE"},
    {146, "PSTAN"},
    {147, "FULL"},
    {148, "FRONT"},
    {149, "REAR"},
    {150, "SADDLE"},
    {151, "MILL"},
    {152, "THRU"},
    {153, "DEEP"},
    {154, "TRAV"},
    {155, "SETOOL"},
    {156, "SETANG"},
    {157, "HOLDER"},
    {158, "MANUAL"},
    {159, "ADJUST"},
    {160, "CUTANG"},
    {161, "NOW"},
    {162, "NEXT"},
    {163, "DRILL"},
    {164, "BINARY"},
    {165, "BCD"},
    {166, "PART"},
    {167, "REAM"},
    {168, "TAP"},
    {169, "CAM"},
    {170, "ZIGZAG"},
    {171, "RETAIN"},
    {172, "OMIT"},
    {173, "AVOID"},
    {174, "RANDOM"},
    {175, "AT"},
    {176, "GRID"},
    {176, "ANTSPI"},
    {180, "GAPLES"},
    {181, "NORMPS"},
    {182, "NORMDS"},
    {183, "TANDS"},
    {184, "FAN"},
    // clpost's own codes for minor words APT360 did not have (lathe and thread vocabulary).
    {901, "AIR"},
    {902, "CHAMFR"},
    {903, "CUTS"},
    {904, "DEPTH"},
    {905, "DIAM"},
    {906, "FINCUT"},
    {907, "FORM"},
    {908, "FPM"},
    {909, "FPR"},
    {910, "INCH"},
    {911, "INCHES"},
    {912, "METRIC"},
    {913, "MILLIMETERS"},
    {914, "MM"},
    {915, "MMPM"},
    {916, "MMPR"},
    {917, "OFFSET"},
    {918, "OSETNO"},
    {919, "PERMIN"},
    {920, "PERREV"},
    {921, "RETURN"},
    {922, "SMM"},
    {923, "TAPER"},
    {924, "THREAD"},
    {925, "TLANGL"},
    {926, "TOOL"},
    {927, "UNDCUT"},
};

struct SubtypeEntry {
  int32_t type;
  int64_t subtype;
  std::string_view name;
};

constexpr SubtypeEntry kSubtypes[] = {
    {kMotion, 1, "INDIRP"},   {kMotion, 2, "INDIRV"},    {kMotion, 3, "FROM"},
    {kMotion, 4, "GODLTA"},   {kMotion, 5, "GOTO"},      {kMotion, 8, "SRFVCT"},
    {kTool, 2, "TOLER"},      {kTool, 4, "INTOL"},       {kTool, 5, "OUTTOL"},
    {kTool, 6, "CUTTER"},     {kMultiAxis, 1, "TLAXIS"}, {kMultiAxis, 2, "MULTAX"},
    {kMultiAxis, 3, "MAXDP"}, {kMultiAxis, 4, "NUMPTS"}, {kMultiAxis, 5, "THICK"},
    {kMultiAxis, 6, "NOPS"},  {kMultiAxis, 7, "AUTOPS"}, {kMultiAxis, 8, "GOUGCK"},
};

constexpr Entry kSurfaces[] = {
    {1, "POINT"},  {2, "LINE"}, {3, "PLANE"},   {4, "CIRCLE"},
    {5, "CYLNDR"}, {8, "CONE"}, {11, "VECTOR"}, {13, "SPHERE"},
};

template <size_t N>
std::string_view name_of(const Entry (&table)[N], int64_t code) {
  for (const Entry& e : table)
    if (e.code == code) return e.name;
  return {};
}

template <size_t N>
int64_t code_of(const Entry (&table)[N], std::string_view name) {
  for (const Entry& e : table)
    if (e.name == name) return e.code;
  return -1;
}

// NCL's codes (NCCS NCL's vocabulary, src/nclfiles/nclvoc.ncl in its public sources) for the
// words clpost's tables and interpreter know: the post words of 2000 records (NCL's own where
// they differ from APT360's: END 499, GOHOME 17, OPSKIP 1012, INTOL 1064, UNITS 841, REMARK
// 1091, …) and the minor words (MMPM 315, MMPR 316, DEPTH 510, RETURN 322, SMM 505, …).
constexpr Entry kNclMajors[] = {
    {2, "STOP"},      {3, "OPSTOP"},    {5, "RAPID"},     {7, "RETRCT"},    {10, "UNLOAD"},
    {15, "RESET"},    {17, "GOHOME"},   {129, "PENUP"},   {130, "PENDWN"},  {499, "END"},
    {802, "DNTCUT"},  {803, "CUT"},     {841, "UNITS"},   {1001, "PLUNGE"}, {1002, "HEAD"},
    {1003, "MODE"},   {1004, "CLEARP"}, {1005, "TMARK"},  {1006, "REWIND"}, {1007, "CUTCOM"},
    {1008, "REVERS"}, {1009, "FEDRAT"}, {1010, "DELAY"},  {1011, "AIR"},    {1012, "OPSKIP"},
    {1013, "LEADER"}, {1014, "PPLOT"},  {1015, "MACHIN"}, {1016, "MCHTOL"}, {1017, "PIVOTZ"},
    {1019, "SEQNO"},  {1020, "INTCOD"}, {1021, "DISPLY"}, {1022, "AUXFUN"}, {1023, "CHECK"},
    {1024, "POSTN"},  {1025, "TOOLNO"}, {1026, "ROTABL"}, {1027, "ORIGIN"}, {1028, "SAFETY"},
    {1029, "ARCSLP"}, {1030, "COOLNT"}, {1031, "SPINDL"}, {1033, "TURRET"}, {1035, "ROTHED"},
    {1036, "THREAD"}, {1037, "TRANS"},  {1042, "OVPLOT"}, {1043, "LETTER"}, {1044, "PPRINT"},
    {1045, "PARTNO"}, {1046, "INSERT"}, {1048, "PREFUN"}, {1049, "COUPLE"}, {1050, "PITCH"},
    {1052, "MDEND"},  {1054, "CYCLE"},  {1055, "LOADTL"}, {1056, "SELCTL"}, {1057, "CLRSRF"},
    {1059, "DRAFT"},  {1060, "CLAMP"},  {1061, "PLABEL"}, {1062, "MAXDPM"}, {1063, "SLOWDN"},
    {1064, "INTOL"},  {1065, "LPRINT"}, {1074, "SELECT"}, {1075, "LOAD"},   {1080, "OUTTOL"},
    {1091, "REMARK"},
};

constexpr Entry kNclMinors[] = {
    {1, "ATANGL"},   {8, "LEFT"},     {9, "LENGTH"},    {10, "MINUS"},   {14, "NOX"},
    {15, "NOY"},     {16, "NOZ"},     {19, "PLUS"},     {23, "RADIUS"},  {24, "RIGHT"},
    {25, "SCALE"},   {28, "TIMES"},   {30, "UNIT"},     {33, "XYPLAN"},  {37, "YZPLAN"},
    {39, "NORMPS"},  {41, "ZXPLAN"},  {50, "OPEN"},     {52, "LAST"},    {53, "NOMORE"},
    {57, "START"},   {59, "CCLW"},    {60, "CLW"},      {61, "MEDIUM"},  {62, "HIGH"},
    {63, "LOW"},     {65, "DECR"},    {66, "INCR"},     {67, "GRID"},    {68, "ROTREF"},
    {71, "ON"},      {72, "OFF"},     {73, "IPM"},      {74, "IPR"},     {75, "CIRCUL"},
    {76, "LINEAR"},  {77, "PARAB"},   {78, "RPM"},      {79, "MAXRPM"},  {80, "TURN"},
    {81, "FACE"},    {82, "BORE"},    {83, "BOTH"},     {84, "XAXIS"},   {85, "YAXIS"},
    {86, "ZAXIS"},   {88, "AUTO"},    {89, "FLOOD"},    {90, "MIST"},    {92, "STEP"},
    {93, "MAIN"},    {94, "SIDE"},    {95, "LINCIR"},   {96, "MAXIPM"},  {97, "REV"},
    {98, "TYPE"},    {107, "THETAR"}, {110, "TRFORM"},  {112, "UP"},     {113, "DOWN"},
    {114, "LOCK"},   {115, "SFM"},    {116, "XCOORD"},  {117, "YCOORD"}, {118, "ZCOORD"},
    {123, "SOLID"},  {124, "DASH"},   {125, "DOTTED"},  {127, "DITTO"},  {128, "PEN"},
    {134, "INTENS"}, {139, "COLLET"}, {140, "AAXIS"},   {141, "BAXIS"},  {142, "CAXIS"},
    {143, "TPI"},    {144, "OPTION"}, {145, "RANGE"},   {148, "FRONT"},  {149, "REAR"},
    {150, "SADDLE"}, {151, "MILL"},   {152, "THRU"},    {153, "DEEP"},   {154, "TRAV"},
    {157, "HOLDER"}, {158, "MANUAL"}, {159, "ADJUST"},  {160, "CUTANG"}, {161, "NOW"},
    {162, "NEXT"},   {163, "DRILL"},  {168, "TAP"},     {170, "ZIGZAG"}, {172, "OMIT"},
    {182, "ARC"},    {189, "AT"},     {197, "DWELL"},   {237, "CAM"},    {246, "ORIENT"},
    {260, "PART"},   {262, "REAM"},   {280, "RAPTO"},   {281, "FEDTO"},  {296, "MM"},
    {303, "INCHES"}, {315, "MMPM"},   {316, "MMPR"},    {322, "RETURN"}, {326, "RANDOM"},
    {327, "AVOID"},  {328, "CONST"},  {329, "RETAIN"},  {505, "SMM"},    {510, "DEPTH"},
    {617, "TOOL"},   {628, "SPLINE"}, {629, "SLOPE"},   {630, "PERPTO"}, {634, "CENTER"},
    {637, "PARLEL"}, {638, "XLARGE"}, {639, "YLARGE"},  {640, "ZLARGE"}, {641, "XSMALL"},
    {642, "YSMALL"}, {643, "ZSMALL"}, {646, "TANTO"},   {649, "TRANSL"}, {652, "IN"},
    {653, "OUT"},    {654, "POSX"},   {655, "POSY"},    {656, "POSZ"},   {657, "NEGX"},
    {658, "NEGY"},   {659, "NEGZ"},   {662, "LARGE"},   {663, "SMALL"},  {666, "OFFSET"},
    {700, "LATHE"},  {714, "TO"},     {715, "PAST"},    {723, "FAN"},    {727, "INTOF"},
    {729, "PSTAN"},  {730, "SAME"},   {732, "MODIFY"},  {733, "XYROT"},  {734, "YZROT"},
    {735, "ZXROT"},  {816, "ALL"},    {819, "CROSS"},   {820, "NORMAL"}, {821, "MIRROR"},
    {822, "INVERS"}, {904, "BLACK"},  {906, "BLUE"},    {907, "RED"},    {908, "GREEN"},
    {961, "CHAMFR"}, {1011, "AIR"},   {1036, "THREAD"}, {1073, "CHUCK"},
};

}  // namespace

std::string_view major_name(int64_t code) {
  return name_of(kMajors, code);
}
int64_t major_code(std::string_view name) {
  return code_of(kMajors, name);
}
bool is_text_major(int64_t code) {
  return code >= 1044 && code <= 1046;
}

std::string_view minor_name(int64_t code) {
  // Minor codes are small: a direct table, as every GOTO-free record asks for them.
  static const auto table = [] {
    std::array<std::string_view, 1024> t{};
    for (auto it = std::rbegin(kMinors); it != std::rend(kMinors); ++it)
      t[static_cast<size_t>(it->code)] = it->name;
    return t;
  }();
  if (code < 0 || code >= static_cast<int64_t>(table.size())) return {};
  return table[static_cast<size_t>(code)];
}
int64_t minor_code(std::string_view name) {
  return code_of(kMinors, name);
}

std::string_view ncl_major_name(int64_t code) {
  return name_of(kNclMajors, code);
}
int64_t ncl_major_code(std::string_view name) {
  return code_of(kNclMajors, name);
}
bool ncl_is_text_major(int64_t code) {
  return (code >= 1044 && code <= 1046) || code == 1091;
}
std::string_view ncl_minor_name(int64_t code) {
  return name_of(kNclMinors, code);
}
int64_t ncl_minor_code(std::string_view name) {
  return code_of(kNclMinors, name);
}

std::string_view subtype_name(int32_t type, int64_t subtype) {
  for (const SubtypeEntry& e : kSubtypes)
    if (e.type == type && e.subtype == subtype) return e.name;
  return {};
}
int64_t subtype_code(int32_t type, std::string_view name) {
  for (const SubtypeEntry& e : kSubtypes)
    if (e.type == type && e.name == name) return e.subtype;
  return -1;
}

std::string_view surface_name(int64_t type) {
  return name_of(kSurfaces, type);
}

bool is_known_type(int64_t type, bool ncl) {
  if (ncl && (type == kNclCutterDisplay || type == kNclHeader)) return true;
  return type == kSequence || type == kPostWord || type == kSurface || type == kMotion ||
         type == kTool || type == kMultiAxis || type == kFini;
}

}  // namespace clpost::cldata
