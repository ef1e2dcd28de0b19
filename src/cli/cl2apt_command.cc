#include "cli/cl2apt_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <cstdio>

#include "cli/post_file.h"
#include "reader/cldata_reader.h"
#include "support/diagnostics.h"
#include "support/input_file.h"
#include "support/output_file.h"

namespace clpost {

namespace {

// Converts an open input whose first bytes are `head`; false on an error (reported).
bool convert(std::FILE* in, std::string_view head, const cldata::Layout& layout,
             const std::string& name, OutputFile& out, Diagnostics& diags, size_t& statements) {
  CldataReader reader(layout, head, in, diags);
  reader.on_comment([&](std::string_view c) { out.write(fmt::format("$$ {}\n", c)); });
  Statement st;
  while (reader.next(st)) {
    out.write(st.lines.front());
    out.write("\n");
    ++statements;
  }
  // Last, so that line k is record k.
  out.write(fmt::format("$$ {}: binary CLDATA ({} layout), written as APT by clpost cl2apt\n", name,
                        layout.name));
  return !diags.has_errors();
}

}  // namespace

Cl2AptOutcome cl2apt_file(const Cl2AptRequest& req) {
  Cl2AptOutcome r;
  const std::string name = display_name(req.input);
  Diagnostics diags(name);
  InputFile input;
  std::string error;
  std::string head(cldata::known_layouts().front().header_bytes() * 64, '\0');
  const cldata::Layout* layout = nullptr;
  if (!input.open(req.input, error)) {
    diags.error({}, {}, error);
  } else {
    head.resize(std::fread(head.data(), 1, head.size(), input.get()));
    layout = cldata::detect_layout(head);
    if (layout == nullptr)
      diags.error({}, {},
                  "not a binary CLDATA file (cl2apt converts binary CL records to APT text)");
  }
  OutputFile out;
  if (layout != nullptr && !out.open(req.output, error)) {
    diags.error({}, {}, fmt::format("cannot write '{}': {}", req.output, error));
  } else if (layout != nullptr &&
             convert(input.get(), head, *layout, name, out, diags, r.statements)) {
    r.ok = out.commit(error);
    if (!r.ok) diags.error({}, {}, fmt::format("cannot write '{}': {}", req.output, error));
  }
  if (!r.ok) out.abort();
  r.diagnostics = diags.render_all();
  return r;
}

CLI::App* add_cl2apt_command(CLI::App& app, Cl2AptRequest& req) {
  CLI::App* c = app.add_subcommand("cl2apt", "Write a binary CLDATA file as APT source text");
  c->add_option("input", req.input, "Binary CL file ('-' for standard input)")->required();
  c->add_option("-o,--output", req.output, "APT file (default: standard output)");
  return c;
}

int run_cl2apt_command(const Cl2AptRequest& req) {
  const Cl2AptOutcome r = cl2apt_file(req);
  std::fputs(r.diagnostics.c_str(), stderr);
  return r.ok ? 0 : 1;
}

}  // namespace clpost
