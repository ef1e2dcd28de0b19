#pragma once
// Posting CL text in the interpreter's tests: a shipped machine without block numbers and
// without its program header (the header's own tests, cycle_time_test.cc, load the machine as
// shipped), plus any --set overrides, and the program, rendered diagnostics and error count of a
// post.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "interpreter/post.h"
#include "machine/machine_loader.h"
#include "machine/machine_test_util.h"

namespace clpost::test {

struct Posted {
  std::string nc;
  std::string diags;
  size_t errors = 0;
};

inline Machine load(const std::string& name, std::vector<std::string> sets = {}) {
  Machine m;
  std::string errors;
  // The caller's sets win.
  sets.insert(sets.begin(), {"block_numbers.enabled=false", "templates.program_header=[]"});
  EXPECT_TRUE(load_machine(name, {CLPOST_SOURCE_DIR}, sets, shipped_controls(), m, errors))
      << errors;
  return m;
}

inline Posted post(const std::string& cl, const Machine& m) {
  PostedText r = post_text(cl, m, "t.cl");
  return Posted{r.program, r.diags.render_all(), r.diags.error_count()};
}

}  // namespace clpost::test
