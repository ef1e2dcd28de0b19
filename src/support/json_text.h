#pragma once
// JSON text pieces shared by the plan output and the batch report.
#include <string>
#include <string_view>

namespace clpost {

// A JSON string literal, quotes included (invalid UTF-8 becomes U+FFFD).
std::string json_string(std::string_view s);

}  // namespace clpost
