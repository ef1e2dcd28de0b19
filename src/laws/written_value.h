#pragma once
// Numbers as the control reads them once written: a cycle's words are chosen, then expanded
// with the control's law from exactly what the NC text will say (rounding, scale), so that
// "exact or fall back" compares what the control will really cut.
#include <string>
#include <string_view>

#include "machine/machine.h"
#include "planner/thread_plan.h"

namespace clpost {

// `v` as the control reads it once written in the machine's format `f` (an address or a named
// format), the scale undone; never -0.
double as_read(const Machine& m, std::string_view f, double v);
double as_read(const NumberFormat& nf, double v);
// One least increment of format `f`, in unscaled units.
double least_increment(const Machine& m, std::string_view f);
double least_increment(const NumberFormat& nf);
// The nearest value format `f` writes that is not below (above) `v` beyond floating noise.
double read_up(const Machine& m, std::string_view f, double v);
double read_down(const Machine& m, std::string_view f, double v);
// A plan point as a positioning block writes it (X in the X format, diameter or radius).
Vec2 point_as_read(const Machine& m, Vec2 p);

// The revolutions over the thread's length (its travel along the axis its lead is measured on,
// P1 to P2, or the path's ends for a single-pass or chained path); at least 1. A lead written
// off by e is off by e x turns at the thread's end.
double thread_turns(const ThreadPlan& plan);

// Why `lead`, the lead the control reads from the word `word` (written in format `format`), does
// not cut the plan's lead within `tol` over the thread's turns; "" when it does. Every emitter
// checks its lead word with it: a lead off by a last digit is far off at the end of a long thread.
std::string lead_mismatch(const Machine& m, const ThreadPlan& plan, double lead,
                          std::string_view word, std::string_view format, double tol);
// The same for the plan's lead written as `address` in format `format` ("F", "g76_lead").
std::string lead_word_mismatch(const Machine& m, const ThreadPlan& plan, std::string_view address,
                               std::string_view format, double tol);

// Why the lead of `plan` as synchronized moves (G33, G32) write it — the TPI word
// (threading.tpi_address) for a thread given in threads per inch, else threading.lead_address,
// or lead_address_x where the X travel dominates, in its format — does not cut the plan's lead
// within `tol` over the thread's turns; "" when it does.
std::string sync_lead_mismatch(const Machine& m, const ThreadPlan& plan, double tol);

}  // namespace clpost
