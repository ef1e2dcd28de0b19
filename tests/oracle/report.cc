// How a difference is shown: enough to reproduce it and see it without running anything.
#include <cstdio>
#include <sstream>

#include "differential.h"

namespace oracle {

namespace {

std::string numbered(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  char buf[16];
  for (int n = 1; std::getline(in, line); ++n) {
    std::snprintf(buf, sizeof buf, "%4d  ", n);
    out += buf + line + "\n";
  }
  return out;
}

std::string events_around(const std::vector<Event>& model, size_t index) {
  std::string out;
  const size_t from = index >= 2 ? index - 2 : 0;
  for (size_t i = from; i < model.size() && i <= index + 1; ++i)
    out +=
        (i == index ? "    > " : "      ") + std::to_string(i) + ": " + describe(model[i]) + "\n";
  return out;
}

}  // namespace

namespace {

std::string run_report(const ProgramResult& r, const RunDifference& run) {
  const Difference& d = run.first;
  std::string t = "  with block delete " + std::string(run.block_delete ? "on" : "off") + ": " +
                  run.klass + "\n";
  if (d.found) {
    t += "    event " + std::to_string(d.index) + ": " + d.field + ": " + d.detail + "\n";
    t += "    model: " + (d.have_model ? describe(d.model) : "(no event)") + "\n";
    t += std::string(r.control == Control::kLinuxcnc ? "    rs274: " : "    read:  ") +
         (d.have_rs274 ? describe(d.rs274) : "(no event)") + "\n";
  }
  if (!run.message.empty()) t += "    " + run.message + (run.message.back() == '\n' ? "" : "\n");
  std::vector<Event> events;
  for (const Event& e : r.model)
    if (!run.block_delete || !e.skipped) events.push_back(e);
  if (d.found && !events.empty())
    t += "    the model's events there:\n" + events_around(events, d.index);
  return t;
}

}  // namespace

std::string report(const ProgramResult& r) {
  std::string t = "seed " + std::to_string(r.seed) + ": " + r.klass + "\n";
  for (size_t i = 1; i < r.classes.size(); ++i) t += "  also: " + r.classes[i] + "\n";
  if (!r.message.empty()) t += "  " + r.message + (r.message.back() == '\n' ? "" : "\n");
  for (const RunDifference& run : r.runs) t += run_report(r, run);
  t += "--- CL (oracle_run --seed " + std::to_string(r.seed) + ")\n" + numbered(r.cl);
  if (!r.nc.empty()) t += "--- NC (" + r.machine + ")\n" + numbered(r.nc);
  return t;
}

std::string summary_text(const Summary& s) {
  char head[160];
  std::snprintf(head, sizeof head,
                "%s: %d programs in %.1f s: %d differ from the model, %d refused\n",
                s.machine.c_str(), s.programs, s.seconds, s.differing, s.refused);
  std::string t = head;
  for (const auto& [klass, c] : s.classes) {
    char line[64];
    std::snprintf(line, sizeof line, "  %5d programs, first seed %-10u ", c.programs, c.first_seed);
    t += line + klass + "\n";
  }
  for (const auto& [klass, c] : s.refusals) {
    char line[80];
    std::snprintf(line, sizeof line, "  %5d refused, first seed %-10u ", c.programs, c.first_seed);
    t += line + klass + "\n";
  }
  return t;
}

}  // namespace oracle
