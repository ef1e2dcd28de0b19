// The registry's read-back side: each control's ControlReadback (simulator/control_readback.h),
// compiled into the simulator stage with the controls' *_readback.cc files.
#include "controls/fanuc/fanuc_readback.h"
#include "controls/haas/haas_readback.h"
#include "controls/heidenhain/heidenhain_readback.h"
#include "controls/linuxcnc/linuxcnc_readback.h"
#include "controls/sinumerik/sinumerik_readback.h"
#include "simulator/control_readback.h"

namespace clpost::sim {

namespace {

bool sinumerik_call(State& s, const NcBlock& b) {
  return cycle99_call(s, b) || cycle98_call(s, b);
}

// Plain ISO (no cycle of its own).
constexpr ControlReadback kIso{};
constexpr ControlReadback kSinumerik{nullptr, sinumerik_call, {}, "DIAMON", "DIAMOF"};
constexpr ControlReadback kFanuc{fanuc_g76};
constexpr ControlReadback kHaas{haas_g76};
constexpr ControlReadback kHeidenhain{heidenhain_g31,
                                      nullptr,
                                      "G31 has no G80: the thread cycle's contour is not closed",
                                      {},
                                      {},
                                      true};
constexpr ControlReadback kLinuxcnc{linuxcnc_g76, nullptr, {}, "G7", "G8"};

// ThreadCycle order.
constexpr const ControlReadback* kAll[] = {&kIso,  &kSinumerik,  &kFanuc,
                                           &kHaas, &kHeidenhain, &kLinuxcnc};
static_assert(std::size(kAll) == kThreadCycleNames.size(), "a read-back for every control");

}  // namespace

const ControlReadback& control_readback(ThreadCycle c) {
  switch (c) {
    case ThreadCycle::kNone:
      return kIso;
    case ThreadCycle::kCycle99:
      return kSinumerik;
    case ThreadCycle::kFanucG76:
      return kFanuc;
    case ThreadCycle::kHaasG76:
      return kHaas;
    case ThreadCycle::kHeidenhainG31:
      return kHeidenhain;
    case ThreadCycle::kLinuxcncG76:
      return kLinuxcnc;
  }
  return kIso;
}

CycleReader loop_reader(ThreadLoop l) {
  switch (l) {
    case ThreadLoop::kG33:
      return nullptr;
    case ThreadLoop::kG92:
      return g92_cycle;  // Fanuc's, Haas's too
  }
  return nullptr;
}

std::span<const ControlReadback* const> control_readbacks() {
  return kAll;
}

}  // namespace clpost::sim
