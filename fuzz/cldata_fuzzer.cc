// libFuzzer target: arbitrary bytes as the records of a binary CLDATA file (the layout the first
// bytes are — NCL's begins with its header record —, else APT360's, its big-endian twin or NCL's
// by the last byte), through the binary reader, the interpreter, the planner and the writer on
// generic-lathe. Then the property cl2apt rests on: the statements'
// APT text, read by the text reader, gives the same statements (a difference aborts). Inputs
// whose first bytes are a CLDATA file of that layout also go through ClReader's detection from
// a FILE*, as `clpost part.cl` reads them, to the same number of statements.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz_post.h"
#include "reader/cldata_layout.h"
#include "reader/cldata_reader.h"

namespace {

const clpost::Machine* g_generic = nullptr;

std::string describe(const clpost::Statement& s) {
  std::string d = std::to_string(static_cast<int>(s.form)) + "|" + std::string(s.major);
  for (const clpost::Arg& a : s.args) {
    d += a.is_number() ? "|#" : "|w";
    d += a.text;
    if (a.is_number()) d += "=" + std::to_string(a.number);
  }
  if (s.form == clpost::Statement::Form::kText) d += "|'" + std::string(s.text) + "'";
  return d;
}

// The binary reader, keeping each statement's description and APT text on the way.
struct Recording {
  clpost::CldataReader& reader;
  std::vector<std::string> statements;
  std::string apt;
  bool next(clpost::Statement& st) {
    if (!reader.next(st)) return false;
    statements.push_back(describe(st));
    apt.append(st.lines.front()).append("\n");
    return true;
  }
  bool gave_up() const { return reader.gave_up(); }
  uint32_t line() const { return reader.record(); }
  size_t bytes_read() const { return reader.bytes_read(); }
};

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_generic = new clpost::Machine(clpost::fuzz::shipped_machine("generic-lathe"));
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace clpost;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // The layout the bytes are; else the last byte's top two bits pick one (the APT360 seeds end
  // in 0: APT360's).
  const auto layouts = cldata::known_layouts();
  const cldata::Layout* detected = cldata::detect_layout(bytes);
  const cldata::Layout& layout =
      detected != nullptr ? *detected
                          : layouts[size > 0 ? (data[size - 1] >> 6) % layouts.size() : 0];
  Diagnostics diags("fuzz.cl");
  CldataReader reader(layout, bytes, diags);
  Recording rec{reader, {}, {}};
  fuzz::post(rec, diags, *g_generic, PostOptions{});

  Diagnostics text_diags("fuzz.apt");
  ClReader text(rec.apt, text_diags);
  Statement st;
  size_t i = 0;
  for (; text.next(st); ++i) {
    if (i >= rec.statements.size() || describe(st) != rec.statements[i]) {
      std::fprintf(stderr, "statement %zu differs:\n  binary: %s\n  text:   %s\n", i,
                   i < rec.statements.size() ? rec.statements[i].c_str() : "(none)",
                   describe(st).c_str());
      std::abort();
    }
  }
  if (i != rec.statements.size() || text_diags.has_errors()) {
    std::fprintf(stderr, "APT text read back: %zu of %zu statements\n%s", i, rec.statements.size(),
                 text_diags.render_all().c_str());
    std::abort();
  }

  if (cldata::detect_layout(bytes) == &layout) {
    std::FILE* f = fmemopen(const_cast<uint8_t*>(data), size, "rb");
    if (f != nullptr) {
      Diagnostics file_diags("fuzz.cl");
      ClReader file_reader(f, file_diags);
      size_t n = 0;
      while (file_reader.next(st)) ++n;
      std::fclose(f);
      if (n != rec.statements.size()) {
        std::fprintf(stderr, "FILE* input: %zu statements, memory: %zu\n", n,
                     rec.statements.size());
        std::abort();
      }
    }
  }
  return 0;
}
