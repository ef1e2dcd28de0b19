// The thinned backplot path: hand-made paths where the points that must survive are known, the
// note, and identical thread sections drawn once with their count.
#include "plot/path_thinner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "plot/backplot_svg.h"
#include "plot/thread_section.h"
#include "support/angles.h"

namespace clpost {
namespace {

Move mv(MoveKind k, Vec2 from, Vec2 to) {
  Move m;
  m.kind = k;
  m.from = from;
  m.to = to;
  return m;
}

// Feeds through `points` (x radius, z), one move per consecutive pair.
std::vector<Move> feeds(const std::vector<Vec2>& points) {
  std::vector<Move> out;
  for (size_t i = 1; i < points.size(); ++i)
    out.push_back(mv(MoveKind::kFeed, points[i - 1], points[i]));
  return out;
}

ThinnedPath thinned(const std::vector<Move>& moves, ThinOptions o = {}) {
  PathThinner t(o);
  for (const Move& m : moves) t.add(m);
  return t.finish(LengthUnit::kMm);
}

void expect_move(const Move& m, MoveKind k, Vec2 from, Vec2 to) {
  EXPECT_EQ(m.kind, k);
  EXPECT_DOUBLE_EQ(m.from.x, from.x);
  EXPECT_DOUBLE_EQ(m.from.z, from.z);
  EXPECT_DOUBLE_EQ(m.to.x, to.x);
  EXPECT_DOUBLE_EQ(m.to.z, to.z);
}

TEST(PathThinner, ACollinearRunCollapsesToItsEnds) {
  std::vector<Vec2> pts;
  for (int i = 0; i <= 100; ++i) pts.push_back({10, -1.0 * i});
  const ThinnedPath p = thinned(feeds(pts));
  ASSERT_EQ(p.path.moves.size(), 1u);
  expect_move(p.path.moves[0], MoveKind::kFeed, {10, 0}, {10, -100});
  EXPECT_EQ(p.measure.total(), 100u);
  EXPECT_DOUBLE_EQ(p.measure.length[1], 100);
  EXPECT_EQ(simplified_note(p), "path simplified: 100 moves drawn as 1 (tolerance 0.4 px)");
}

TEST(PathThinner, ATurnAboveTheAngleSurvives) {
  // Z 0..-50 along X 10, then a 45 degree turn to (20, -60): the corner stays. A point 0.001 mm
  // off the line in the middle of the first leg (a turn of 0.002 degrees, far under a pixel:
  // the scale is 1094 px / 66 mm, about 16.6 px/mm) goes.
  const ThinnedPath p = thinned(feeds({{10, 0}, {10.001, -25}, {10, -50}, {20, -60}}));
  ASSERT_EQ(p.path.moves.size(), 2u);
  expect_move(p.path.moves[0], MoveKind::kFeed, {10, 0}, {10, -50});
  expect_move(p.path.moves[1], MoveKind::kFeed, {10, -50}, {20, -60});
  // A turn of 3 degrees (under kTurnDegrees) after a 50 mm leg: the corner sits 50 mm *
  // sin(1.5 deg) = 1.3 mm (22 px) off the chord that would replace it, so it stays too.
  const double s = std::sin(radians(3)), c = std::cos(radians(3));
  const ThinnedPath q = thinned(feeds({{10, 0}, {10, -50}, {10 + 50 * s, -50 - 50 * c}}));
  EXPECT_EQ(q.path.moves.size(), 2u);
}

TEST(PathThinner, MovesShorterThanAPixelMergeWhateverTheirTurn) {
  // A zigzag of 0.005 mm steps (0.08 px) between two long straight legs: merged away. (10,-50),
  // where the first leg ends and the direction turns into the zigzag, stays while streaming;
  // thinned once more at the end, the two legs, now joined in line, merge too.
  std::vector<Vec2> pts = {{10, 0}, {10, -50}};
  for (int i = 1; i <= 10; ++i) pts.push_back({i % 2 == 1 ? 10.004 : 10.0, -50 - 0.003 * i});
  pts.push_back({10, -100});
  const ThinnedPath p = thinned(feeds(pts));
  ASSERT_EQ(p.path.moves.size(), 1u);
  expect_move(p.path.moves[0], MoveKind::kFeed, {10, 0}, {10, -100});
}

TEST(PathThinner, ARapidsEndsSurvive) {
  std::vector<Move> m = feeds({{10, 0}, {10, -10}, {10, -20}});
  m.push_back(mv(MoveKind::kRapid, {10, -20}, {10, -30}));
  for (const Move& f : feeds({{10, -30}, {10, -40}, {10, -50}})) m.push_back(f);
  const ThinnedPath p = thinned(m);
  ASSERT_EQ(p.path.moves.size(), 3u);
  expect_move(p.path.moves[0], MoveKind::kFeed, {10, 0}, {10, -20});
  expect_move(p.path.moves[1], MoveKind::kRapid, {10, -20}, {10, -30});
  expect_move(p.path.moves[2], MoveKind::kFeed, {10, -30}, {10, -50});
}

TEST(PathThinner, EveryThreadIsKeptAndIdenticalOnesDrawnOnce) {
  // Two collinear thread moves stay two; 500 repeats of them (identical threads) draw once.
  std::vector<Move> m;
  for (int i = 0; i < 500; ++i) {
    m.push_back(mv(MoveKind::kRapid, {12, 2}, {9, 2}));
    m.push_back(mv(MoveKind::kThread, {9, 2}, {9, -10}));
    m.push_back(mv(MoveKind::kThread, {9, -10}, {9, -20}));
    m.push_back(mv(MoveKind::kRapid, {9, -20}, {12, -20}));
    m.push_back(mv(MoveKind::kRapid, {12, -20}, {12, 2}));
  }
  const ThinnedPath p = thinned(m);
  ASSERT_EQ(p.path.moves.size(), 5u);
  expect_move(p.path.moves[1], MoveKind::kThread, {9, 2}, {9, -10});
  expect_move(p.path.moves[2], MoveKind::kThread, {9, -10}, {9, -20});
  EXPECT_EQ(p.measure.moves[3], 1000u);
  EXPECT_EQ(simplified_note(p), "path simplified: 2 500 moves drawn as 5 (tolerance 0.4 px)");
}

TEST(PathThinner, NothingMergedNoNote) {
  const ThinnedPath p = thinned(feeds({{10, 0}, {10, -50}, {20, -60}}));
  EXPECT_EQ(p.path.moves.size(), 2u);
  EXPECT_FALSE(p.simplified());
  EXPECT_EQ(simplified_note(p), "");
}

TEST(PathThinner, TheBudgetCoarsensTheTolerance) {
  // 20 000 moves of a zigzag 1 mm across every 1 mm along Z over 20 000 mm: at 1094 px for
  // about 22 000 mm (0.05 px/mm) each move is 0.07 px, all under a pixel. With a budget of
  // 100 moves the zigzag still fits: every move merges into one line 1 mm (0.05 px) wide.
  std::vector<Vec2> pts;
  for (int i = 0; i <= 20000; ++i) pts.push_back({i % 2 == 0 ? 10.0 : 11.0, -1.0 * i});
  ThinOptions o;
  o.budget = 100;
  const ThinnedPath p = thinned(feeds(pts), o);
  EXPECT_LE(p.path.moves.size(), 100u);
  EXPECT_EQ(p.measure.total(), 20000u);
  // A zigzag 40 mm across every 1 mm (each move 40 mm, 2 px, turning 177 degrees): the budget
  // doubles the tolerance until the moves are shorter than it.
  pts.clear();
  for (int i = 0; i <= 20000; ++i) pts.push_back({i % 2 == 0 ? 10.0 : 50.0, -1.0 * i});
  const ThinnedPath q = thinned(feeds(pts), o);
  EXPECT_LE(q.path.moves.size(), 100u);
  EXPECT_GT(q.tolerance_px, 0.4);
}

TEST(PathThinner, PastTheBudgetMovesAreCountedNotDrawn) {
  // 100 distinct rapids (each 10 mm from X 20 down to X 10, one Z apart) with a budget of 40:
  // rapids keep their ends, so once they fill half the budget (20) no more are drawn.
  std::vector<Move> m;
  for (int i = 0; i < 100; ++i) m.push_back(mv(MoveKind::kRapid, {20, -1.0 * i}, {10, -1.0 * i}));
  ThinOptions o;
  o.budget = 40;
  const ThinnedPath p = thinned(m, o);
  EXPECT_EQ(p.path.moves.size(), 20u);
  EXPECT_EQ(p.dropped, 80u);
  EXPECT_EQ(simplified_note(p),
            "path simplified: 100 moves drawn as 20 (tolerance 0.4 px); 80 moves past the budget "
            "not drawn");
}

ThreadSection section(std::string title, double depth) {
  ThreadSection s;
  s.title = std::move(title);
  s.pitch = 1.5;
  s.lead = 1.5;
  s.depth = depth;
  s.passes = {{1, 0, 0.5, 0.2, PassKind::kRough}, {2, 0, depth, 0.3, PassKind::kFinish}};
  return s;
}

TEST(SectionGroups, IdenticalThreadsOnceWithTheirCount) {
  SectionGroups g;
  for (int i = 0; i < 3; ++i) g.add(section("thread at line " + std::to_string(10 + i), 0.92));
  g.add(section("thread at line 40", 0.8));
  const std::vector<ThreadSection> d = g.drawn();
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].title, "thread at line 10 \u00d73 (3 identical threads)");
  EXPECT_EQ(d[1].title, "thread at line 40");
  EXPECT_EQ(g.total(), 4u);
  EXPECT_EQ(g.left_out(), 0u);
}

TEST(SectionGroups, AtMostSoManyDistinctOnes) {
  SectionGroups g;
  for (size_t i = 0; i < kMaxDrawnSections + 5; ++i)
    g.add(section("t", 0.5 + 0.01 * static_cast<double>(i)));
  EXPECT_EQ(g.drawn().size(), kMaxDrawnSections);
  EXPECT_EQ(g.left_out(), 5u);
}

TEST(ThinnedBackplot, TheNoteIsInThePicture) {
  std::vector<Vec2> pts;
  for (int i = 0; i <= 100; ++i) pts.push_back({10, -1.0 * i});
  const ThinnedPath p = thinned(feeds(pts));
  const std::string svg = backplot_svg(p, nullptr, "t", simplified_note(p));
  EXPECT_NE(svg.find(">path simplified: 100 moves drawn as 1 (tolerance 0.4 px)</text>"),
            std::string::npos);
  EXPECT_NE(svg.find(">100 moves: 100 feed (100 mm)</text>"), std::string::npos);
}

}  // namespace
}  // namespace clpost
