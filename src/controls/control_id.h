#pragma once
// The registered controls, named by the threading cycle a machine file selects them with
// (threading.cycle). This list and the registry files beside it (registry_output.cc,
// registry_readback.cc) are the only places outside a control's folder that name one; each switch
// over ThreadCycle has no `default:`, so a control added here and forgotten there does not
// compile. docs/adding-a-control.md walks through adding one.
#include <array>
#include <cstdint>
#include <string_view>

namespace clpost {

enum class ThreadCycle : uint8_t {
  kNone,           // plain ISO: G33 loops and emulation (controls without a cycle of their own)
  kCycle99,        // SINUMERIK: CYCLE99, CYCLE98 for chains, CYCLE96 undercuts (sinumerik/)
  kFanucG76,       // Fanuc: two-block G76, G92 (fanuc/)
  kHaasG76,        // Haas: one-block G76, Fanuc's G92 (haas/)
  kHeidenhainG31,  // HEIDENHAIN DIN: G31 … G80 (heidenhain/)
  kLinuxcncG76     // LinuxCNC: G76 (linuxcnc/)
};

// threading.cycle's value for each, in ThreadCycle order.
inline constexpr std::array<std::string_view, 6> kThreadCycleNames = {
    "none", "cycle99", "fanuc_g76", "haas_g76", "heidenhain_g31", "linuxcnc_g76"};
static_assert(kThreadCycleNames.size() == static_cast<size_t>(ThreadCycle::kLinuxcncG76) + 1,
              "a name for every ThreadCycle");

}  // namespace clpost
