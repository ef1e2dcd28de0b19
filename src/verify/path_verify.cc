#include "verify/path_verify.h"

#include <fmt/format.h>

#include <cmath>

#include "emitters/cut_pass.h"

namespace clpost {

namespace {

bool near(Vec2 a, Vec2 b, double tol) {
  return std::fabs(a.x - b.x) <= tol && std::fabs(a.z - b.z) <= tol;
}

bool same_kind(const ClMotion& c, const Move& mv) {
  return c.rapid ? mv.kind == MoveKind::kRapid
                 : mv.kind == MoveKind::kFeed || mv.kind == MoveKind::kArcCw ||
                       mv.kind == MoveKind::kArcCcw;
}

// The first move from `from` that ends at `c` (of its kind when `kind`), or moves.size().
size_t find_move(const std::vector<Move>& moves, size_t from, const ClMotion& c, double tol,
                 bool kind) {
  for (size_t j = from; j < moves.size(); ++j)
    if (near(moves[j].to, c.to, tol) && (!kind || same_kind(c, moves[j]))) return j;
  return moves.size();
}

}  // namespace

PathReport verify_path(const std::vector<ClMotion>& cl, const Toolpath& path, const Machine& m,
                       const VerifyOptions& options, Diagnostics& nc_diags) {
  PathReport r;
  if (cl.empty()) return r;
  const double shown = options.tolerance > 0 ? options.tolerance : cut_tolerance(m);
  const double tol = shown + 1e-9;
  // Every move in order, the entries from an unknown position among them.
  std::vector<Move> moves;
  moves.reserve(path.moves.size() + path.entries.size());
  size_t e = 0;
  for (size_t i = 0; i <= path.moves.size(); ++i) {
    for (; e < path.entries.size() && path.entries[e].before == i; ++e)
      moves.push_back(path.entries[e].move);
    if (i < path.moves.size()) moves.push_back(path.moves[i]);
  }
  const double xs = m.diameter_output ? 2 : 1;
  std::string first;
  size_t next = 0;
  for (const ClMotion& c : cl) {
    const size_t j = find_move(moves, next, c, tol, true);
    if (j < moves.size()) {
      next = j + 1;
      continue;
    }
    const size_t k = find_move(moves, next, c, tol, false);
    const std::string where = fmt::format("X{:.4f} Z{:.4f}", c.to.x * xs, c.to.z);
    std::string why =
        k < moves.size()
            ? fmt::format("{}:{}: {} is reached by a {} move, the CL {} there", options.plan_name,
                          c.line, where, moves[k].kind == MoveKind::kRapid ? "rapid" : "feed",
                          c.rapid ? "rapids" : "cuts")
            : fmt::format("{}:{}: {} is not reached by the program in order", options.plan_name,
                          c.line, where);
    if (r.problems++ == 0) first = why;
    const Move* at = k < moves.size() ? &moves[k] : next > 0 ? &moves[next - 1] : nullptr;
    nc_diags.error(SourceLoc{at ? static_cast<uint32_t>(at->line) : 0, 1}, {}, "motion at " + why);
    if (k < moves.size()) next = k + 1;
  }
  r.text = r.problems == 0
               ? fmt::format("motions: {} CL end points, every one reached in order, within {:g}\n",
                             cl.size(), shown)
               : fmt::format(
                     "FAILED: {} of {} CL end points not reached as the CL moves; the "
                     "first: {}\n",
                     r.problems, cl.size(), first);
  return r;
}

}  // namespace clpost
