// The kind of tool a tool change loads, as the CL says it (docs/millturn.md): LOADTL/…,MILL, the
// tool data before it (TDATA/MILL, TLDATA/MILL, TOOLNO/…,MILL), else the CL's mode (APPLY/MILL,
// SET/MODE,MILL, MODE/MILL). What the tool change selects with it is tool_paths.cc's.
#include "interpreter/tool_kind.h"

#include <fmt/format.h>

#include "interpreter/statement_table.h"

namespace clpost {

namespace {

// The kind word `a` (MILL, TURN, LATHE) as a ToolKind, or none.
std::optional<ToolKind> kind_word(const Arg& a) {
  if (a.is("MILL")) return ToolKind::kMill;
  if (a.is("TURN") || a.is("LATHE")) return ToolKind::kTurn;
  return std::nullopt;
}

ToolKindWord said(const Statement& st, ToolKind k, std::string_view how) {
  return ToolKindWord{k, fmt::format("{}/{}", st.major, how), st.loc.line};
}

}  // namespace

std::optional<ToolKindWord> loadtl_kind(const PostState& s, const Statement& st, size_t first,
                                        SourceLoc& at) {
  at = st.loc;
  for (size_t i = first + 1; i < st.args.size(); ++i) {
    if (auto k = kind_word(st.args[i])) {
      at = st.args[i].loc;
      return said(st, *k, fmt::format("…,{}", st.args[i].text));
    }
  }
  if (s.next_tool.kind) return s.next_tool.kind;
  return s.cl_mode;
}

std::optional<ToolKindWord> toolno_kind(const Statement& st) {
  std::optional<ToolKindWord> kind;
  for (size_t i = 1; i < st.args.size(); ++i)  // Fusion's TOOLNO/n,MILL,…; ICAM's …,(MILL,TURN),…
    if (st.args[i].is("MILL") || st.args[i].is("TURN"))
      kind = ToolKindWord{st.args[i].is("MILL") ? ToolKind::kMill : ToolKind::kTurn,
                          fmt::format("TOOLNO/…,{}", st.args[i].text), st.loc.line};
  return kind;
}

// TDATA/MILL|TURN,… (CATIA) and TLDATA/MILL|TURN,… (NX): the kind of the tool the next tool
// change loads; the rest of the record is tool geometry clpost does not need.
void tdata_stmt(PostState& s, const Statement& st) {
  if (!st.args.empty())
    if (auto k = kind_word(st.args[0])) s.next_tool.kind = said(st, *k, st.args[0].text);
  // NX's TLDATA/MILL,d,… and TLDATA/DRILL,MILL,d,…: the first number is the cutter's diameter.
  if (st.major == "TLDATA" && !st.args.empty() && (st.args[0].is("MILL") || st.args[0].is("DRILL")))
    for (const Arg& a : st.args)
      if (a.is_number()) {
        if (a.number > 0 && within_limits(a.number)) describe_diameter(s, a.number);
        break;
      }
  skipped_stmt(s, st);
}

// APPLY/MILL|TURN (ICAM, Fusion, NX-to-APT), SET/MODE,MILL|TURN, MODE/MILL|LATHE (NCL): the
// kind of the tools loaded from here on whose own records do not say.
void apply_stmt(PostState& s, const Statement& st) {
  const size_t i = st.major == "SET" && !st.args.empty() && st.args[0].is("MODE") ? 1 : 0;
  if (st.major == "SET" && i == 0) return unknown_stmt(s, st);
  const std::optional<ToolKind> k = i < st.args.size() ? kind_word(st.args[i]) : std::nullopt;
  if (!k) return unknown_stmt(s, st);
  s.cl_mode = said(st, *k, i ? fmt::format("MODE,{}", st.args[i].text) : st.args[i].text);
}

}  // namespace clpost
