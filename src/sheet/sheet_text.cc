#include "sheet/sheet_text.h"

#include <fmt/format.h>

#include "machine/machine.h"
#include "support/number_text.h"

namespace clpost {

std::string feed_text(const FeedUsed& f, LengthUnit units) {
  const char* u = units == LengthUnit::kInch ? "in" : "mm";
  switch (f.mode) {
    case FeedMode::kPerMinute:
      return fmt::format("{} {}/min", num_text(f.value), u);
    case FeedMode::kPerRev:
      return fmt::format("{} {}/rev", num_text(f.value), u);
  }
  return num_text(f.value);
}

std::string speed_text(const SpeedUsed& s, LengthUnit units) {
  if (!s.css) return fmt::format("{} rpm", num_text(s.value));
  return fmt::format("{} {}", num_text(s.value), units == LengthUnit::kInch ? "ft/min" : "m/min");
}

std::string tool_name(const ToolTime& t) {
  return t.tool < 0 ? std::string("(none)") : fmt::format("T{}", t.tool);
}

std::string reach_text(const ToolTime& t, bool diameter) {
  if (t.x_min > t.x_max) return {};
  const double xs = diameter_factor(diameter);
  return fmt::format("X{:.3f} to X{:.3f}, Z{:.3f} to Z{:.3f}", t.x_min * xs, t.x_max * xs, t.z_min,
                     t.z_max);
}

const OutputUsed* output_at(const std::vector<OutputUsed>& outputs, uint32_t line) {
  for (const OutputUsed& o : outputs)
    if (o.loc.line == line) return &o;
  return nullptr;
}

std::string fallback_text(const OutputUsed& o) {
  return unfit_reasons(o.unfit);
}

size_t tool_changes(const CycleTime& t) {
  size_t n = 0;
  for (const ToolTime& tt : t.tools) n += listed(tt) && tt.tool >= 0;
  return n;
}

}  // namespace clpost
