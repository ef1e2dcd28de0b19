#pragma once
// What the fuzz targets share: posting CL text on a machine through post() (interpreter/post.h),
// as `clpost` does, into memory.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "interpreter/post.h"
#include "machine/machine.h"
#include "machine/machine_loader.h"
#include "machine/machine_test_util.h"
#include "planner/plan_format.h"
#include "reader/cl_reader.h"
#include "support/diagnostics.h"
#include "support/sink.h"
#include "writer/nc_program.h"

namespace clpost::fuzz {

// A shipped machine; aborts when it does not load (the fuzz run would be meaningless).
inline Machine shipped_machine(const char* name) {
  Machine m;
  std::string errors;
  if (!load_machine(name, {CLPOST_SOURCE_DIR}, {}, shipped_controls(), m, errors)) {
    std::fprintf(stderr, "fuzz: cannot load machine %s:\n%s", name, errors.c_str());
    std::abort();
  }
  return m;
}

// Every shipped machine, sorted by name (the listing `clpost machines` uses), loaded; aborts when
// there is none or one does not load. A target's input picks one by index into it.
inline std::vector<Machine> shipped_machines() {
  std::vector<Machine> out;
  for (const std::string& name : testing::shipped_machine_names())
    out.push_back(shipped_machine(name.c_str()));
  if (out.empty()) {
    std::fprintf(stderr, "fuzz: no shipped machines in %s/machines\n", CLPOST_SOURCE_DIR);
    std::abort();
  }
  return out;
}

// Reads CL from `reader` and posts it on `m` through post(): the NC program, the rendered
// diagnostics and the thread plans as text and JSON. Returns the number of errors. `Reader` is
// ClReader or any reader post() takes (the binary CLDATA target passes its own).
template <class Reader>
size_t post(Reader& reader, Diagnostics& diags, const Machine& m, PostOptions opts,
            std::string* nc_out = nullptr) {
  StringSink sink;
  std::vector<ThreadPlan> plans;
  const PostSummary summary = clpost::post(reader, m, sink, diags, opts, [&](const ThreadPlan& p) {
    if (plans.size() < 64) plans.push_back(p);
  });
  const LengthUnit units = summary.units;
  std::string text = diags.render_all();
  text += plan_to_text("fuzz.cl", units, plans);
  text += plan_to_json("fuzz.cl", units, plans);
  if (nc_out != nullptr) *nc_out = std::move(sink.out);
  return diags.error_count();
}

}  // namespace clpost::fuzz
