#include "emitters/written_value.h"

#include <charconv>
#include <cmath>
#include <string>

#include "writer/number_format.h"

namespace clpost {

namespace {
double unscale(const NumberFormat& nf) {
  return nf.scale > 0 ? nf.scale : 1;
}
}  // namespace

double as_read(const Machine& m, std::string_view f, double v) {
  const NumberFormat& nf = m.format_for(f);
  const std::string s = number_text(v, nf);
  double r = 0;
  std::from_chars(s.data(), s.data() + s.size(), r);
  r /= unscale(nf);
  return r == 0 ? 0 : r;
}

double least_increment(const Machine& m, std::string_view f) {
  const NumberFormat& nf = m.format_for(f);
  return std::pow(10.0, -nf.decimals) / unscale(nf);
}

double read_up(const Machine& m, std::string_view f, double v) {
  double r = as_read(m, f, v);
  if (r < v - 1e-9) r = as_read(m, f, r + least_increment(m, f));
  return r;
}

double read_down(const Machine& m, std::string_view f, double v) {
  double r = as_read(m, f, v);
  if (r > v + 1e-9) r = as_read(m, f, r - least_increment(m, f));
  return r;
}

Vec2 point_as_read(const Machine& m, Vec2 p) {
  const double k = m.diameter_output ? 2 : 1;
  return {as_read(m, "X", k * p.x) / k, as_read(m, "Z", p.z)};
}

}  // namespace clpost
