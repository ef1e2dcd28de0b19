#pragma once
#include <string>
#include <vector>

namespace clpost {

// Where shipped machines/ and posts/ are looked for, in order: $CLPOST_DATA_DIR, the installed
// share/clpost beside the binary, and the source tree the binary was built from.
std::vector<std::string> data_dirs();

}  // namespace clpost
