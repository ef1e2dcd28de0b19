// The date a sheet shows (sheet.h): --date, else SOURCE_DATE_EPOCH (reproducible builds'
// convention, so tests and goldens do not change with the clock), else now.
#include <fmt/chrono.h>
#include <fmt/format.h>

#include <charconv>
#include <chrono>
#include <ctime>
#include <string_view>

#include "sheet/sheet.h"

namespace clpost {

namespace {

std::string utc_text(std::time_t t) {
  std::tm tm{};
  gmtime_r(&t, &tm);
  return fmt::format("{:%Y-%m-%d %H:%M} UTC", tm);
}

}  // namespace

bool sheet_date(const std::string& given, const char* epoch, std::string& date,
                std::string& error) {
  if (!given.empty()) {
    date = given;
    return true;
  }
  if (epoch != nullptr && *epoch != '\0') {
    const std::string_view e(epoch);
    long long seconds = 0;
    const auto [end, ec] = std::from_chars(e.data(), e.data() + e.size(), seconds);
    if (ec != std::errc() || end != e.data() + e.size() || seconds < 0) {
      error = fmt::format("SOURCE_DATE_EPOCH '{}' is not a whole number of seconds", e);
      return false;
    }
    date = utc_text(static_cast<std::time_t>(seconds));
    return true;
  }
  date = utc_text(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now()));
  return true;
}

}  // namespace clpost
