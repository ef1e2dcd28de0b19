#pragma once
// The code tables of binary CLDATA (ISO 3592 as APT360 writes it): record types, the major
// words of type-2000 records, the minor words, the subtypes of motion (5000), tool and
// tolerance (6000) and multi-axis (9000) records, and the surface types of 3000 records.
// Source: ../shared/reference/cam/apt360_notes.txt. Words APT360 did not know but clpost's CL
// vocabulary uses (UNITS, MMPR, DEPTH, ...) have clpost's own codes (kExtMajor, kExtMinor
// ranges), so that every statement clpost reads can be written as a binary record too.
#include <cstdint>
#include <string_view>

namespace clpost::cldata {

enum RecordType : int32_t {
  kSequence = 1000,   // ISN: the part program's statement number (subtype)
  kPostWord = 2000,   // post-processor statement: subtype = major word code
  kSurface = 3000,    // surface data (canonical forms)
  kMotion = 5000,     // cutter locations: subtype 3 FROM, 5 GOTO, 6 continuation, ...
  kTool = 6000,       // tool and tolerance data: CUTTER, INTOL, ...
  kMultiAxis = 9000,  // MULTAX and the like
  kFini = 14000,
  // NCL's own (postworks/pwmacro/clfile.f): a cutter for display only, and the clfile header
  // (the clfile's name, date, time, CAM system and version).
  kNclCutterDisplay = 7100,
  kNclHeader = 7400,
};

inline constexpr int32_t kMotionContinuation = 6;
inline constexpr int32_t kExtMajor = 1900;  // clpost's own major codes: 1901...
inline constexpr int64_t kExtMinor = 900;   // clpost's own minor codes: 901...

// Name of a type-2000 major code (1 END ... 1072 MAGTAP, 1901... clpost's); empty if unknown.
std::string_view major_name(int64_t code);
// Code of a type-2000 major word; -1 if none.
int64_t major_code(std::string_view name);
// PARTNO, PPRINT, INSERT: the record's words are text.
bool is_text_major(int64_t code);

// Name of a minor word code; empty if unknown.
std::string_view minor_name(int64_t code);
// Code of a minor word; -1 if none.
int64_t minor_code(std::string_view name);

// The same with NCL's codes (its vocabulary): PPRINT, PARTNO, INSERT and REMARK carry text. Only
// the words clpost's tables and interpreter know; unknown: empty, -1.
std::string_view ncl_major_name(int64_t code);
int64_t ncl_major_code(std::string_view name);
bool ncl_is_text_major(int64_t code);
std::string_view ncl_minor_name(int64_t code);
int64_t ncl_minor_code(std::string_view name);

// Major word of a record of type 5000, 6000 or 9000 by its subtype; empty if unknown
// (5000/6, a continuation, is the major of the record it continues).
std::string_view subtype_name(int32_t type, int64_t subtype);
// Subtype of such a major word for `type`; -1 if none.
int64_t subtype_code(int32_t type, std::string_view name);

// Name of a surface type of a 3000 record's canonical form (4 CIRCLE, ...); empty if unknown.
std::string_view surface_name(int64_t type);

// The record types above; NCL's own only with `ncl`.
bool is_known_type(int64_t type, bool ncl = false);

}  // namespace clpost::cldata
