// HEIDENHAIN DIN (CNC PILOT): G31 on its contour … G80 (heidenhain_emitter.h, heidenhain_law.h)
// and its read-back.
#include "controls/heidenhain/heidenhain_codes.h"
#include "controls/heidenhain/heidenhain_emitter.h"
#include "controls/heidenhain/heidenhain_readback.h"
#include "controls/heidenhain/heidenhain_templates.h"
#include "machine/control.h"

namespace clpost {

namespace {

// HEIDENHAIN CNC PILOT DIN Programming: [METRIC]/[INCH] program sections, G33 thread cutting,
// G94/G95 feed per minute / per revolution.
constexpr FixedCode kHeidenhainFixedCodes[] = {
    {"metric", "[METRIC]", "selects millimetres"},
    {"inch", "[INCH]", "selects inches"},
    {"thread", "G33", "is a thread cut"},
    {"feed_per_min", "G94", "is feed per minute"},
    {"feed_per_rev", "G95", "is feed per revolution"},
};

constexpr const TemplateSpec* kHeidenhainTemplates[] = {&tmpl::kHeidenhainG31};

}  // namespace

extern const Control kHeidenhainControl{.name = "heidenhain",
                                        .cycle = "heidenhain_g31",
                                        .cycle_emitter = []() -> std::unique_ptr<Emitter> {
                                          return std::make_unique<HeidenhainG31Emitter>();
                                        },
                                        .readback = &sim::kHeidenhainReadback,
                                        .fixed_codes = kHeidenhainFixedCodes,
                                        // Positions to 1 µm (MANUALplus 4110 manual, "Accuracy");
                                        // its inch step 0.0001 in: docs/cl-meaning.md.
                                        .inch_length_increment = 0.0001,
                                        // CNC PILOT 4290 manual, "Program section codes": the
                                        // UNIT is the PROGRAM HEAD's, set when the program is
                                        // created ("not possible to post-edit"), else control
                                        // parameter 1; "[INCH]" is a comment.
                                        .one_unit_per_program = true,
                                        .codes = kHeidenhainCodes,
                                        .templates = kHeidenhainTemplates};

}  // namespace clpost
