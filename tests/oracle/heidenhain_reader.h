#pragma once
// A small reader of a HEIDENHAIN CNC PILOT / MANUALplus DIN (DIN PLUS) lathe program: the program
// text in, the oracle's events out (events.h: mm, X a radius), as the control runs it with block
// delete off or on. Written from HEIDENHAIN's manuals and the project's references (each
// meaning's source beside its code, docs/cl-meaning.md "How the oracle reads a HEIDENHAIN DIN
// program"); it shares no code with src/ and none with the Fanuc reader's meanings (only the
// ControlRun it returns). What the manuals leave to a machine parameter is refused, not guessed.
#include <optional>
#include <string_view>

#include "events.h"
#include "fanuc_reader.h"  // ControlRun: the events, or where and why the control stops

namespace oracle {

// `unit_inch`: the control's parameter 1, the unit of a program whose PROGRAM HEAD gives none
// (the machine's setting; nullopt: not known, a program that needs it is refused).
ControlRun heidenhain_events(std::string_view program, bool block_delete,
                             std::optional<bool> unit_inch);

}  // namespace oracle
