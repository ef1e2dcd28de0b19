#pragma once
// "Did you mean" suggestions for misspelt names (machine keys, codes, templates, machines).
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace clpost {

// The edit distance between `a` and `b`, or `limit` when it is `limit` or more.
size_t edit_distance(std::string_view a, std::string_view b, size_t limit);

// " (did you mean 'x'?)" for the closest name of `valid` within two edits of `name`, else "".
std::string did_you_mean(std::string_view name, const std::vector<std::string_view>& valid);
std::string did_you_mean(std::string_view name, const std::vector<std::string>& valid);

}  // namespace clpost
