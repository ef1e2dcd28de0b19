#pragma once
// Test helpers for the control simulation: a shipped machine, loaded from machines/ as is.
#include <gtest/gtest.h>

#include <string>

#include "machine/machine_loader.h"
#include "machine/machine_test_util.h"

namespace clpost::testing {

inline Machine shipped(const std::string& name) {
  Machine m;
  std::string errors;
  EXPECT_TRUE(load_machine(name, {CLPOST_SOURCE_DIR}, {}, shipped_controls(), m, errors)) << errors;
  return m;
}

}  // namespace clpost::testing
