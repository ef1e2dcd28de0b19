// Words CAM systems write around lathe work that carry no motion of their own: SYN/ (synonyms),
// DNTCUT/CUT (moves tracked, not cut), tool data written before the tool change it describes
// (CATIA's TOOLNO/, TPRINT/, CUTTER/) and SWITCH/ (the tool-tip quadrant). See
// docs/reading-cam-output.md, "The vocabulary".
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "interpreter/statement_table.h"
#include "interpreter/tool_kind.h"

namespace clpost {

namespace {

// The pair `SYN/…,'a','b'` at args i, i+1; false (reported) when it is not two texts.
bool read_synonym(PostState& s, const Statement& st, size_t i) {
  for (size_t k = i; k < i + 2; ++k) {
    if (k >= st.args.size()) {
      error(s, st, st.args.back().loc,
            "SYN/ takes pairs of quoted words: SYN/'word','replacement'[,…]: the last word has no "
            "replacement");
      return false;
    }
    if (!st.args[k].is_text() && !st.args[k].is_word()) {
      error(s, st, st.args[k].loc,
            fmt::format("SYN/ takes quoted words, found {}", describe_arg(st.args, k)));
      return false;
    }
  }
  return true;
}

}  // namespace

void syn_stmt(PostState& s, const Statement& st) {
  if (st.args.empty()) {
    error(s, st, st.loc, "SYN/ takes pairs of quoted words: SYN/'word','replacement'");
    return;
  }
  for (size_t i = 0; i < st.args.size(); i += 2) {
    if (!read_synonym(s, st, i)) return;
  }
  for (size_t i = 0; i < st.args.size(); i += 2) {
    std::string word(st.args[i].text), to(st.args[i + 1].text);
    std::transform(word.begin(), word.end(), word.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    std::transform(to.begin(), to.end(), to.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    // To a comment ('$$…'): the word is ignored from here on.
    const bool ignored = to.starts_with("$$");
    if (ignored) to.clear();
    note_once(s, st, "syn:" + word,
              ignored ? fmt::format("SYN/: {} statements are ignored from here on", word)
                      : fmt::format("SYN/: {} stands for {} from here on", word, to));
    auto it = std::find_if(s.synonyms.begin(), s.synonyms.end(),
                           [&](const auto& p) { return p.first == word; });
    if (it != s.synonyms.end())
      it->second = to;
    else
      s.synonyms.emplace_back(std::move(word), std::move(to));
  }
}

// PPFUN/…: options of ICAM's own post, skipped (a note) — except PPFUN/3,n,'text', the table's
// message where it has no output for an operation: NC_THREAD_WITHOUT_TAP_HEAD writes
// PPFUN/3,8,'NC_THREAD_WITHOUT_TAP_HEAD_cycle_not_available' where the cycle would be, and the
// holes' GOTOs that follow would be posted as plain moves. An error quoting the table's text.
void ppfun_stmt(PostState& s, const Statement& st) {
  if (!st.args.empty() && st.args[0].is_number() && st.args[0].number == 3) {
    for (const Arg& a : st.args) {
      if (!a.is_text()) continue;
      error(s, st, a.loc,
            fmt::format("PPFUN/3: ICAM's table reports '{}' here: the operation has no output "
                        "in the table, and the holes after it would be posted as plain moves",
                        a.text));
      s.in_cycle = true;  // its holes, up to CYCLE/OFF, are not moves (as a refused cycle's)
      return;
    }
  }
  skipped_stmt(s, st);
}

void dntcut_stmt(PostState& s, const Statement&) {
  s.dntcut = true;
}

void cut_stmt(PostState& s, const Statement&) {
  s.dntcut = false;
}

// TOOLNO/n,TURN,n,0,quadrant,nose radius,set X,set Z,feed,feed unit,speed,speed unit,dir,ON,
// life,NOTE (CATIA's NC_TOOL_CHANGE_LATHE); TOOLNO/n[,…] for other tools: the tool number and,
// for a turning tool, its tip quadrant, nose radius and default feed and speed, kept for the
// tool change that follows.
void toolno_stmt(PostState& s, const Statement& st) {
  double n = 0;
  if (!number_arg(s, st, 0, "a tool number", n)) return;
  ToolInfo& t = s.next_tool;
  t.number = static_cast<int>(n);
  if (std::optional<ToolKindWord> kind = toolno_kind(st)) t.kind = kind;
  if (st.args.size() < 2 || !st.args[1].is("TURN")) return;
  auto number_at = [&](size_t i) -> std::optional<double> {
    if (i < st.args.size() && st.args[i].is_number() && within_limits(st.args[i].number))
      return st.args[i].number;
    return std::nullopt;
  };
  if (auto q = number_at(4); q && *q >= 1 && *q <= 9 && *q == std::floor(*q))
    t.tip_quadrant = static_cast<int>(*q);
  if (auto r = number_at(5); r && *r >= 0) t.nose_radius = *r;
  if (auto f = number_at(8); f && *f > 0 && 9 < st.args.size() && st.args[9].is_word())
    t.feed = fmt::format("{} {}", st.args[8].text, st.args[9].text);
  if (auto v = number_at(10); v && *v > 0 && 11 < st.args.size() && st.args[11].is_word())
    t.speed = fmt::format("{} {}", st.args[10].text, st.args[11].text);
}

void describe_diameter(PostState& s, double d) {
  const bool unmoved = s.tool.number >= 0 && s.stats.motions == s.tool.motions_at_change;
  (unmoved ? s.tool : s.next_tool).diameter = d;
}

void tprint_stmt(PostState& s, const Statement& st) {
  s.next_tool.text = std::string(st.text);
}

// CUTTER/d: the cutter diameter. On a lathe CATIA writes twice the nose radius (NC_CUTTER_LATHE:
// CUTTER/2*%MFG_NOSE_RADIUS); milling cutters have more values, of which the first is the
// diameter. Kept for TLLFT/TLRGT geometric motion, and as the tool's diameter (describe_diameter).
void cutter_stmt(PostState& s, const Statement& st) {
  double d = 0;
  if (!number_arg(s, st, 0, "a cutter diameter", d)) return;
  if (d < 0) {
    error(s, st, st.args[0].loc, fmt::format("cutter diameter must not be negative, got {}", d));
    return;
  }
  s.cutter_diameter = d;
  if (d > 0) describe_diameter(s, d);
}

// SWITCH/n[,m]: the tool-tip quadrant (1..9) of the tool in use, for nose-radius compensation.
void switch_stmt(PostState& s, const Statement& st) {
  double q = 0;
  if (!number_arg(s, st, 0, "a tool-tip quadrant", q)) return;
  if (q < 0 || q > 9 || q != std::floor(q)) {
    error(s, st, st.args[0].loc,
          fmt::format("SWITCH/ takes a tool-tip quadrant 0..9, got {}", st.args[0].text));
    return;
  }
  s.tool.tip_quadrant = static_cast<int>(q);
}

// The synonym of major word `major`, or nullptr: SYN/ has not named it.
const std::string* synonym_of(const PostState& s, std::string_view major) {
  for (const auto& [word, to] : s.synonyms)
    if (word == major) return &to;
  return nullptr;
}

}  // namespace clpost
