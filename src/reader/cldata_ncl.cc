// NCL's own records (postworks/pwmacro/clfile.f and src/nclf/aptsrc.f in NCL's public sources):
// the clfile header (7400) as NCL's APT source writes it, REMARK name date time CAM version;
// MULTAX (9000, subtype 0 ON, 1 OFF, no words); a cutter record (6000, whatever its subtype) as
// APT's seven-parameter CUTTER (cldata_ncl.h); a display-only cutter (7100) skipped.
#include "reader/cldata_ncl.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "reader/cldata_reader.h"
#include "reader/cldata_words.h"
#include "support/angles.h"

namespace clpost {

using namespace cldata;

namespace {}  // namespace

std::array<double, 7> cldata::ncl_apt_cutter(std::span<const double> ncl) {
  std::array<double, 7> p{};
  std::copy_n(ncl.begin(), std::min<size_t>(ncl.size(), 7), p.begin());
  if (ncl.size() >= 5) {
    if (p[3] != 0) p = {p[0], p[3], p[2], p[0] / 2 - p[3], p[4], p[5], p[1]};
    return {p[0], p[1], p[3], p[4], p[6], p[5], p[2]};
  }
  const double r = p[1], a = p[3];
  double d = p[0], e = 0, f = 0;
  if (r != 0) {
    e = d / 2 - r, f = r;
    if (a > 0 && a < 90) {
      d = d - 2 * r + 2 * r * std::tan(radians(90 - a) / 2);
    } else if (a < 0 && a > -90) {
      d = d + 2 * r * (std::tan(radians(-a) / 2) + 1) / std::tan(radians(90 + a));
    }
  }
  return {d, r, e, f, p[6], a, p[2]};
}

std::optional<bool> CldataReader::ncl_record(Statement& out) {
  switch (header_.type) {
    case kNclHeader:
      in_record_ = false;
      return ncl_header(out);
    case kMultiAxis:
      in_record_ = false;
      return ncl_multax(out);
    case kTool:
      in_record_ = false;
      return ncl_cutter(out);
    case kNclCutterDisplay:
      in_record_ = false;
      comment_of_record();
      return false;
    default:
      return std::nullopt;
  }
}

// REMARK name     date  time  CAM  version, as NCL's APT source begins (asclnm): the name in
// words 1-10, the date in the 11 characters of words 11-12, then a word each.
bool CldataReader::ncl_header(Statement& out) {
  const auto chars = [&](size_t word, size_t n) {
    std::string s;
    for (size_t i = 0; i < n && word * layout_.word_bytes + i < count_ * layout_.word_bytes; ++i) {
      const char c = words_[word * layout_.word_bytes + i];
      s += c == '\0' ? ' ' : c;  // NCL pads its fields with NULs as well as blanks
    }
    return s;
  };
  std::string name = chars(0, 80);
  while (!name.empty() && name.back() == ' ') name.pop_back();
  std::string& text = comment_text_;
  text = fmt::format("{}     {}  {}  {}  {}", name, chars(10, 11), chars(12, 8), chars(13, 8),
                     chars(14, 8));
  return text_statement(out, "REMARK", text);
}

bool CldataReader::ncl_multax(Statement& out) {
  if (header_.subtype != 0 && header_.subtype != 1) {
    error(loc_at(record_at_),
          fmt::format("MULTAX record of subtype {}: NCL writes 0 (ON) or 1 (OFF); the points "
                      "after it could not be read",
                      header_.subtype));
    stop();
    return false;
  }
  multax_ = header_.subtype == 0;
  begin(out, "MULTAX", Statement::Form::kRecord, loc_at(record_at_));
  add_word(out, multax_ ? "ON" : "OFF", loc_at(record_at_));
  finish(out);
  return true;
}

// CUTTER/d,r,e,f,a,b,h of NCL's parameters; a negative diameter (NCL's blade and lathe cutters,
// which its APT source writes as a comment) and a record of no words make no statement.
bool CldataReader::ncl_cutter(Statement& out) {
  std::vector<double> ncl;
  for (size_t i = 0; i < count_; ++i) {
    const uint64_t bits = read_word(layout_, words_ + i * layout_.word_bytes);
    const double v = word_double(bits);
    if (word_code(layout_, bits) || !std::isfinite(v)) {
      error(loc_of_word(i), fmt::format("CUTTER parameter {} is not a finite number", i + 1));
      return false;
    }
    ncl.push_back(v);
  }
  if (ncl.empty() || ncl[0] < 0) {
    comment_of_record();
    return false;
  }
  begin(out, "CUTTER", Statement::Form::kRecord, loc_at(record_at_));
  for (double v : ncl_apt_cutter(ncl)) {
    if (!std::isfinite(v)) {
      error(loc_of_word(0), "CUTTER parameters give no finite APT cutter");
      return false;
    }
    add_number(out, v, loc_of_word(0));
  }
  finish(out);
  return true;
}

}  // namespace clpost
