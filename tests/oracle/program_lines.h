#pragma once
// The line loop every control reader runs (fanuc_reader.cc, sinumerik_reader.cc,
// heidenhain_reader.cc): the program's lines in order, each parsed into the reader's Block and
// run by its Control; an optional ("/") block is passed over when block delete is on; the loop
// stops at the program's end or at the first error, the parser's or the control's, at its line.
#include <string>
#include <string_view>

namespace oracle {

// Control: `bool ended()`, `bool block(const Block&, int line, std::string_view text)` (false:
// the control stops, its `run.error` says why) and `ControlRun run`. Parse: `std::string
// (std::string_view text, Block&)`, empty when the line parses. Skip: `bool (int line,
// std::string_view text)`, a line the control does not run as a block.
template <class Block, class Control, class Parse, class Skip>
void read_program_lines(std::string_view program, bool block_delete, Control& c, Parse parse,
                        Skip skip) {
  for (int line = 1; !program.empty() && !c.ended(); ++line) {
    const size_t nl = program.find('\n');
    const std::string_view text = program.substr(0, nl);
    program = nl == std::string_view::npos ? std::string_view() : program.substr(nl + 1);
    if (skip(line, text)) continue;
    Block b;
    const std::string error = parse(text, b);
    if (error.empty() && b.optional && block_delete) continue;
    if (error.empty() && c.block(b, line, text)) continue;
    c.run.error = error.empty() ? c.run.error : error;
    c.run.error_line = line;
    return;
  }
}

}  // namespace oracle
