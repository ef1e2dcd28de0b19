#include "fanuc_cycles.h"

#include "fanuc_reader_impl.h"

#include <algorithm>
#include <cmath>

namespace oracle {

namespace {

void move(MotionKind kind, CyclePoint to, double lead, std::vector<Event>& out, CyclePoint& at) {
  if (std::abs(to.x - at.x) < 1e-9 && std::abs(to.z - at.z) < 1e-9) return;
  Event e;
  e.motion = kind;
  e.x = to.x, e.z = to.z;
  e.lead = lead;
  out.push_back(e);
  at = to;
}

}  // namespace

// controllers.md, Fanuc G92: "one pass per block (rapid in, threaded cut with the control's
// chamfer, rapid out, rapid back)"; G76 cuts each pass the same way from its start point.
void thread_pass(CyclePoint s, CyclePoint cut, CyclePoint end, double lead,
                 std::vector<Event>& out) {
  CyclePoint at = s;
  move(MotionKind::kRapid, cut, 0, out, at);
  move(MotionKind::kThread, end, lead, out, at);
  move(MotionKind::kRapid, {s.x, end.z}, 0, out, at);
  move(MotionKind::kRapid, s, 0, out, at);
}

// controllers.md, "What public sources confirm", Fanuc G76: "cumulative depth Δd·√n (first cut
// Δd); once an increment would fall below Δdmin every later increment is Δdmin; roughing stops at
// k − d; then m passes at k".
std::vector<double> fanuc_g76_depths(double k, double first, double min_cut, double allowance,
                                     int finish_passes) {
  std::vector<double> depths;
  const double rough = k - allowance;
  bool at_min = false;
  for (int n = 1; first > 0 && (depths.empty() || depths.back() < rough - 1e-9); ++n) {
    const double last = depths.empty() ? 0 : depths.back();
    double d = first * std::sqrt(n);
    at_min = at_min || d - last < min_cut;
    if (at_min) d = last + min_cut;
    depths.push_back(std::min(d, rough));
  }
  for (int i = 0; i < finish_passes; ++i) depths.push_back(k);
  return depths;
}

// controllers.md, "Haas lathe" and "What public sources confirm", Haas G76: "depth of
// successive cuts D·√N for P1/P2 (single / alternating edge, constant amount), constant depth
// for P3/P4". The finishing allowance and the minimum cut (settings 86, 99) are taken as 0: their
// rules are not stated.
std::vector<double> haas_g76_depths(double k, double d, bool constant_depth) {
  std::vector<double> depths;
  for (int n = 1; d > 0; ++n) {
    const double depth = constant_depth ? n * d : d * std::sqrt(n);
    if (depth >= k - 1e-9) break;
    depths.push_back(depth);
  }
  depths.push_back(k);
  return depths;
}

}  // namespace oracle

namespace oracle::fanuc_detail {

// The end point of a cycle block: X (U) and Z (W), U and W from the start point, either one left
// out the cycle's last (modal [0i-T] "Single repetitive cycle").
bool Control::cycle_end(const Block& b, std::optional<double>& x, std::optional<double>& z) {
  if (!x_ || !z_) return fail("a threading cycle from a position the program does not state");
  x = x_, z = z_;
  if (!length(b, 'X', x) || !length(b, 'Z', z)) return false;
  if (!b.find('X') && !b.find('U')) x = cycle_x_;
  if (!b.find('Z') && !b.find('W')) z = cycle_z_;
  if (!x || !z) return fail("a threading cycle without its end point");
  if (!on_) return fail("a threading cycle with the spindle stopped");
  if (!f_given_) return fail("a threading cycle without its lead F");
  cycle_x_ = x, cycle_z_ = z;
  return true;
}

// G92 X Z [R] F [Q]: one pass per block from where the tool is, R the taper (radius, start − end),
// F the lead, Q a start angle (a multi-start thread's; the events do not carry it) [ctl] "G92".
// The thread's pull-out chamfer is parameter 5130 and is read as none.
bool Control::g92(const Block& b) {
  std::optional<double> x, z;
  if (!cycle_end(b, x, z)) return false;
  if (const Word* r = b.find('R')) {
    if (!r->point) return fail("R without a decimal point");
    cycle_r_ = r->value * unit();
  }
  if (b.find('I') || b.find('K') || b.find('P')) return fail("a word G92 does not take");
  std::vector<Event> pass;
  thread_pass({*x_, *z_}, {*x + cycle_r_, *z_}, {*x, *z}, f_ * unit(), pass);
  for (const Event& e : pass) push(e);
  return true;
}

// G76's first block, P<m><r><a> Q<Δdmin> R<d>: finishing passes, chamfer (0.1 leads), tool
// angle, the smallest cut (least increment, no decimal point) and the finishing allowance [ctl].
bool Control::g76_first(const Block& b) {
  const Word *p = b.find('P'), *q = b.find('Q'), *r = b.find('R');
  if (!p || !q || !r) return fail("G76's first block without P, Q or R (parameters 5140-5143)");
  if (p->point || q->point || !r->point) return fail("G76 P, Q without and R with a point");
  const int v = static_cast<int>(p->value);
  g76_ = G76First{v / 10000, v / 100 % 100, v % 100, q->value * increment(), r->value * unit()};
  return true;
}

// Each pass from the start point at its depth's X, the taper's at the start; with a tool angle,
// shifted along the flank by (k − depth)·tan(angle/2) toward the start point, the pass ending at
// Z (the reader's reading: controllers.md says where the passes end is not known).
void Control::g76_passes(const std::vector<double>& depths, CyclePoint end, double k, double taper,
                         double angle, double lead) {
  const CyclePoint s{*x_, *z_};
  const double out = s.x > end.x ? 1 : -1, back = s.z > end.z ? 1 : -1;
  const double flank = std::tan(angle / 2 * 3.14159265358979323846 / 180);
  std::vector<Event> passes;
  for (double depth : depths) {
    const double x = end.x + out * (k - depth);
    thread_pass(s, {x + taper, s.z + back * (k - depth) * flank}, {x, end.z}, lead, passes);
  }
  for (const Event& e : passes) push(e);
}

// G76's second block (Fanuc), X Z R<i> P<k> Q<Δd> F<L>: the passes of fanuc_g76_depths. A
// chamfer is refused: where it sits is not known [ctl].
bool Control::g76(const Block& b) {
  if (d_ == Dialect::kHaas) return haas_g76(b);
  if (!b.find('X') && !b.find('U') && !b.find('Z') && !b.find('W')) return g76_first(b);
  if (!g76_) return fail("G76 without its first block");
  if (g76_->chamfer != 0) return fail("G76 with a chamfer (where it sits is not documented)");
  const Word *p = b.find('P'), *q = b.find('Q'), *r = b.find('R');
  if (!p || !q || p->point || q->point) return fail("G76 P and Q whole, in the least increment");
  if (r && !r->point) return fail("R without a decimal point");
  std::optional<double> x, z;
  if (!cycle_end(b, x, z)) return false;
  const double k = p->value * increment();
  const std::vector<double> depths =
      fanuc_g76_depths(k, q->value * increment(), g76_->min_cut, g76_->allowance, g76_->m);
  g76_passes(depths, {*x, *z}, k, r ? r->value * unit() : 0, g76_->angle, f_ * unit());
  return true;
}

// Haas's one-block G76 X Z [I] K D [A] P [Q] F: K the thread height, D the first cut, A the tool
// angle (none: straight in), P1-P4 the infeed (1, 3 single edge; 2, 4 alternating edges, whose
// shifts are not documented: refused with an angle) [ctl] "Haas lathe".
bool Control::haas_g76(const Block& b) {
  const Word *k = b.find('K'), *d = b.find('D'), *p = b.find('P'), *a = b.find('A');
  const Word* i = b.find('I');
  if (!k || !d || !p || !k->point || !d->point) return fail("Haas G76 without K. and D.");
  const int mode = static_cast<int>(p->value);
  if (mode < 1 || mode > 4) return fail("Haas G76 P other than 1-4");
  const double angle = a ? a->value : 0;
  if (angle != 0 && (mode == 2 || mode == 4)) return fail("Haas G76 alternating with an angle");
  if (i && !i->point) return fail("I without a decimal point");
  std::optional<double> x, z;
  if (!cycle_end(b, x, z)) return false;
  const double height = k->value * unit();
  g76_passes(haas_g76_depths(height, d->value * unit(), mode >= 3), {*x, *z}, height,
             i ? i->value * unit() : 0, angle, f_ * unit());
  return true;
}

}  // namespace oracle::fanuc_detail
