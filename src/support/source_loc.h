#pragma once
#include <cstdint>

namespace clpost {

// A position in a source file. Lines and columns are 1-based; 0 means "unknown".
struct SourceLoc {
  uint32_t line = 0;
  uint32_t col = 0;
};

}  // namespace clpost
