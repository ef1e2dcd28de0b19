// libFuzzer target: arbitrary bytes as a CL file, through the reader, the interpreter, the
// thread planner, the emitters and the NC writer, on generic-lathe (read from memory) or
// linuxcnc-lathe (read through a FILE*, so both LineSource paths are covered): the first byte's
// second bit picks one, so each input costs one post (twice the inputs per second of posting
// both).
#include <cstddef>
#include <cstdint>
#include <cstdio>

#include "fuzz_post.h"

namespace {

const clpost::Machine* g_generic = nullptr;
const clpost::Machine* g_linuxcnc = nullptr;

}  // namespace

// The machines are loaded once, before the first input (a machine that does not load stops the
// run here, not in the middle of it).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_generic = new clpost::Machine(clpost::fuzz::shipped_machine("generic-lathe"));
  g_linuxcnc = new clpost::Machine(clpost::fuzz::shipped_machine("linuxcnc-lathe"));
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace clpost;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The first byte's low bit picks --strict (the text still starts at byte 0).
  PostOptions opts;
  opts.strict = size > 0 && (data[0] & 1) != 0;
  if (size == 0 || (data[0] & 2) == 0) {
    Diagnostics diags("fuzz.cl");
    ClReader reader(text, diags);
    fuzz::post(reader, diags, *g_generic, opts);
  } else {
    std::FILE* f = fmemopen(const_cast<uint8_t*>(data), size, "rb");
    if (f != nullptr) {
      Diagnostics diags("fuzz.cl");
      ClReader reader(f, diags);
      fuzz::post(reader, diags, *g_linuxcnc, opts);
      std::fclose(f);
    }
  }
  return 0;
}
