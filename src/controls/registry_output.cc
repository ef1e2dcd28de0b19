// The registry's output side: each control's thread emitters (emitters/emitter.h), compiled into
// the emitters stage with the controls' *_emitter.cc files.
#include "controls/fanuc/fanuc_emitter.h"
#include "controls/haas/haas_emitter.h"
#include "controls/heidenhain/heidenhain_emitter.h"
#include "controls/linuxcnc/linuxcnc_emitter.h"
#include "controls/sinumerik/cycle96_emitter.h"
#include "controls/sinumerik/cycle98_emitter.h"
#include "controls/sinumerik/cycle99_emitter.h"
#include "controls/sinumerik/sinumerik_templates.h"
#include "emitters/emitter.h"
#include "emitters/emulation_emitter.h"
#include "emitters/undercut_output.h"

namespace clpost {

std::unique_ptr<Emitter> make_cycle_emitter(ThreadCycle c) {
  switch (c) {
    case ThreadCycle::kNone:
      return nullptr;
    case ThreadCycle::kCycle99:
      return std::make_unique<Cycle99Emitter>();
    case ThreadCycle::kFanucG76:
      return std::make_unique<FanucG76Emitter>();
    case ThreadCycle::kHaasG76:
      return std::make_unique<HaasG76Emitter>();
    case ThreadCycle::kHeidenhainG31:
      return std::make_unique<HeidenhainG31Emitter>();
    case ThreadCycle::kLinuxcncG76:
      return std::make_unique<LinuxcncG76Emitter>();
  }
  return nullptr;
}

std::unique_ptr<Emitter> make_loop_emitter(ThreadLoop l) {
  switch (l) {
    case ThreadLoop::kG33:
      return std::make_unique<EmulationEmitter>("G33 loop");
    case ThreadLoop::kG92:
      return std::make_unique<G92Emitter>();
  }
  return nullptr;
}

std::unique_ptr<Emitter> make_chain_emitter(const Machine& m) {
  if (m.templates.count(std::string(tmpl::kCycle98.name)))
    return std::make_unique<Cycle98Emitter>();
  return nullptr;
}

std::unique_ptr<CycleOutput<Undercut>> make_undercut_cycle(const Machine& m) {
  if (m.templates.count(std::string(tmpl::kCycle96.name)))
    return std::make_unique<Cycle96Emitter>();
  return nullptr;
}

}  // namespace clpost
