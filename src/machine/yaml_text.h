#pragma once
// The lines of a YAML file, so diagnostics can show the offending line under its location.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace clpost {

class YamlText {
 public:
  explicit YamlText(std::string_view text) {
    size_t start = 0;
    while (start <= text.size()) {
      size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      std::string_view l = text.substr(start, end - start);
      if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
      lines_.emplace_back(l);
      start = end + 1;
    }
  }
  // 1-based; empty when out of range.
  std::string_view line(uint32_t n) const {
    return n >= 1 && n <= lines_.size() ? std::string_view(lines_[n - 1]) : std::string_view();
  }
  // First line starting with `key:` (top level), 0 when none.
  uint32_t find_key_line(std::string_view key) const {
    for (size_t i = 0; i < lines_.size(); ++i)
      if (lines_[i].starts_with(key) && lines_[i].size() > key.size() &&
          lines_[i][key.size()] == ':')
        return static_cast<uint32_t>(i + 1);
    return 0;
  }

 private:
  std::vector<std::string> lines_;
};

}  // namespace clpost
