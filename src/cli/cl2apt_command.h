#pragma once
// `clpost cl2apt INPUT [-o OUT]`: a binary CLDATA file as APT source text, one statement per
// record, the words by name; records that make no statement (sequence numbers, surface data)
// become `$$` comments. Line k is record k — until a record of several points, written as one
// GOTO line per point — so the text posts to the same NC program as the binary file, down to
// the line numbers it quotes ("thread line 18").
#include <string>

namespace CLI {
class App;
}

namespace clpost {

struct Cl2AptRequest {
  std::string input;         // "-": standard input
  std::string output = "-";  // "-": standard output
};

struct Cl2AptOutcome {
  bool ok = false;
  std::string diagnostics;  // for standard error
  size_t statements = 0;
};

Cl2AptOutcome cl2apt_file(const Cl2AptRequest& req);

// The subcommand's options, and running it (exit status 0, or 1 on an error in the input or
// in writing the output).
CLI::App* add_cl2apt_command(CLI::App& app, Cl2AptRequest& req);
int run_cl2apt_command(const Cl2AptRequest& req);

}  // namespace clpost
