#pragma once
// A small reader of a SINUMERIK 840D (sl) turning program in Siemens mode: the program text in,
// the oracle's events out (events.h: mm, X a radius), as the control runs it with block delete
// (skip level /0) off or on. Written from Siemens' documentation (docs/cl-meaning.md, "How the
// oracle reads a SINUMERIK program", each meaning's source beside its code); it shares no code
// with src/ (not the NC reader, not the laws, not the simulator, not the machine files).
//
// The control it reads for: a turret lathe whose T word changes the tool (MD22550
// TOOL_CHANGE_MODE = 0, "new tool with T", the turning setting), X the transverse axis (MD20100
// DIAMETER_AX_DEF). Every other meaning that is machine data or setting data (the basic system
// of units MD10240, the power-on G codes MD20150, LIMS's setting datum SD43230) is refused, not
// guessed.
#include <string_view>

#include "events.h"
#include "fanuc_reader.h"  // ControlRun

namespace oracle {

ControlRun sinumerik_events(std::string_view program, bool block_delete);

}  // namespace oracle
