#pragma once
// The command line: `clpost [options] INPUT`, `clpost machines`, `clpost check`, `clpost plan`.
// Exit codes: 0 ok, 1 errors in the input, 2 usage or machine-file errors.

namespace clpost {

int run_cli(int argc, char** argv);

}  // namespace clpost
