// libFuzzer target: arbitrary bytes as a machine file (applied on top of generic-lathe, as
// `clpost -m my-lathe.yaml` would after reading its post) or, when the first byte's low bit is
// set, as a post file on an empty machine. A file that loads must then post a CL program that
// uses every template (tool change, spindle rpm and CSS, dwell, stop, threads) without trouble.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_post.h"

namespace {

constexpr const char* kProgram =
    "PARTNO FUZZ PART\n"
    "UNITS/MM\n"
    "LOADTL/7,ADJUST,7\n"
    "SPINDL/SMM,120,CLW,MAXRPM,2000\n"
    "SPINDL/600,RPM,CLW\n"
    "COOLNT/FLOOD\n"
    "FEDRAT/0.2,MMPR\n"
    "RAPID\n"
    "GOTO/15,0,5\n"
    "GOTO/12.5,0,-1.25\n"
    "CIRCLE/10,0,-1.25,0,1,0,2.5\n"
    "GOTO/10,0,-3.75\n"
    "DELAY/1.5\n"
    "DELAY/REV,2\n"
    "OPSTOP\n"
    "THREAD/ON,DEPTH,1.534,CUTS,4,FINCUT,1,0.1,OPTION,1,MMPR,2.5,CHAMFR,2.5\n"
    "GOTO/10,0,2\n"
    "GOTO/10,0,-30\n"
    "THREAD/OFF\n"
    "PITCH/1.5,MMPR\n"
    "THREAD/TURN\n"
    "GOTO/9.2,0,2\n"
    "GOTO/9.2,0,-20\n"
    "COUPLE/ON\n"
    "GOTO/9.1,0,-20\n"
    "GOTO/10.6,0,-21.5\n"
    "COUPLE/OFF\n"
    "PPRINT done\n"
    "SPINDL/OFF\n"
    "STOP\n"
    "FINI\n";

const clpost::Machine* g_base = nullptr;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  g_base = new clpost::Machine(clpost::fuzz::shipped_machine("generic-lathe"));
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace clpost;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const bool is_post = size > 0 && (data[0] & 1) != 0;
  Machine m = is_post ? Machine{} : *g_base;
  m.controls = g_base->controls;  // the set generic-lathe was loaded with
  m.name = "fuzz";
  std::string errors;
  if (!apply_machine_yaml("fuzz.yaml", text, is_post, m, errors)) return 0;
  Diagnostics diags("fuzz.cl");
  ClReader reader(std::string_view(kProgram), diags);
  fuzz::post(reader, diags, m, PostOptions{});
  return 0;
}
