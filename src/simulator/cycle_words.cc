#include "simulator/cycle_words.h"

#include <fmt/format.h>

#include "reader/number.h"

namespace clpost::sim {

uint32_t first_col(const NcBlock& b) {
  return b.words.empty() ? 1 : b.words.front().col;
}

double word_or(const State& s, const NcBlock& b, const char* address, std::string_view format,
               double fallback) {
  const NcWord* w = b.find(address);
  return w != nullptr ? s.value(*w, format) : fallback;
}

bool missing(State& s, const NcBlock& b, const Code& code, const char* words) {
  for (const char* w = words; *w != 0; ++w) {
    if (b.find(std::string(1, *w)) == nullptr) {
      s.error(b.words.empty() ? 1 : b.words.front().col,
              fmt::format("{}{:g} without its {} word", code.address, code.number.value_or(0), *w));
      return true;
    }
  }
  return false;
}

std::map<std::string, size_t> call_fields(std::string_view t) {
  std::map<std::string, size_t> out;
  size_t open = t.find('(');
  if (open == std::string_view::npos) return out;
  size_t index = 0;
  bool quoted = false;
  size_t arg = open + 1;
  for (size_t i = open + 1; i < t.size(); ++i) {
    if (t[i] == '"') quoted = !quoted;
    if (quoted || (t[i] != ',' && t[i] != ')')) continue;
    std::string_view a = t.substr(arg, i - arg);
    size_t b = a.find('{'), e = a.find_first_of(":}", b == std::string_view::npos ? 0 : b);
    if (b != std::string_view::npos && e != std::string_view::npos)
      out[std::string(a.substr(b + 1, e - b - 1))] = index;
    ++index;
    arg = i + 1;
    if (t[i] == ')') break;
  }
  return out;
}

std::optional<CallArgs> CallArgs::find(State& s, const NcBlock& b, const TemplateSpec& spec) {
  const auto tmpl = s.m.templates.find(std::string(spec.name));
  if (tmpl == s.m.templates.end() || tmpl->second.empty()) return std::nullopt;
  std::string_view t = tmpl->second.front();
  const std::string name(t.substr(0, t.find('(')));
  for (const NcCall& c : b.calls)
    if (c.name == name) return CallArgs(s, c, name, call_fields(t));
  return std::nullopt;
}

double CallArgs::arg(const char* field, std::string_view format, double fallback) {
  auto it = fields_.find(field);
  if (it == fields_.end() || it->second >= call_->args.size() || !ok_) return fallback;
  const std::string& a = call_->args[it->second];
  if (a.empty()) return fallback;
  double v = 0;
  if (reader::parse_number(a, v) != reader::NumberStatus::kOk) {
    s_->error(call_->cols[it->second], fmt::format("{} argument {} ({}): invalid number '{}'",
                                                   name_, it->second + 1, field, a));
    ok_ = false;
    return fallback;
  }
  const double scale = s_->m.format_for(format).scale;
  return scale != 0 ? v / scale : v;
}

int CallArgs::whole(double v, const char* n, int lo, int hi) {
  if (!ok_) return lo;
  const std::optional<int> r = s_->whole(v, n, lo, hi, call_->col);
  ok_ = ok_ && r.has_value();
  return r.value_or(lo);
}

}  // namespace clpost::sim
