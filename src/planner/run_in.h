#pragma once
// Run-in and run-out: where a thread's lead is not yet right (docs/threading.md section 15).
//
// The control accelerates the lead axis into every synchronized cut and decelerates it out of
// it; over the first δ1 (run-in) and the last δ2 (run-out) of the cut the lead is wrong. Source:
// Fanuc Series 15i operator's manual, appendix "Incorrect threaded length":
//
//   δ2 = T1·V,   δ1 = (t − T1 + T1·e^(−t/T1))·V  with  e^(−t/T1) = a,
//
// V = R·L/60 the speed of the lead axis (R spindle rpm, L lead; per second), T1 the servo time
// constant (threading.servo_time_constant, "usually 0.033 s"), a the lead error allowed
// (threading.lead_error). With t = −T1·ln a that is δ1 = T1·V·(a − 1 − ln a).
//
// Shops use a short form (HUST H6D-T manual): δ1 = (R·L/1800)·(−1 − ln a), δ2 = R·L/1800. Its
// 1/1800 is T1/60 with T1 taken as 1/30 s (0.0333 rather than 0.033), and it drops the + a of δ1:
// at 1500 rpm and a 2 mm lead it gives 6.009 and 1.667 where the manual's form gives 5.965 and
// 1.65. clpost uses the manual's form (run_in_out); the short form is short_form_run_in_out.
#include <string>

#include "planner/thread_plan.h"

namespace clpost {

// The control facts of the law (threading.servo_time_constant, threading.lead_error).
struct LeadLaw {
  double servo_time_constant = 0.033;  // T1, seconds
  double lead_error = 0.01;            // a, a fraction of the lead
};

struct RunInOut {
  double run_in = 0;   // δ1, along the lead axis
  double run_out = 0;  // δ2
};

// δ1 and δ2 of a cut at `rpm` with `lead` per revolution (lengths in the lead's unit): the
// manual's form above. 0 for a speed or lead that is not positive.
RunInOut run_in_out(double rpm, double lead, const LeadLaw& law);

// The shops' short form, for comparison: δ1 = (R·L/1800)·(−1 − ln a), δ2 = R·L/1800.
RunInOut short_form_run_in_out(double rpm, double lead, double lead_error);

// The largest whole rpm at which a cut `length` long (along the lead axis) at `lead` still has
// some length with the right lead: the run-out, and the run-in too when `run_in_inside` (it lies
// within the cut), shorter than `length` together. 0 when no speed of 1 rpm or more leaves any.
int largest_rpm_with_right_lead(double length, double lead, const LeadLaw& law, bool run_in_inside);

// Sets plan.rpm, run_in and run_out for a thread cut at `rpm` (0: not known; then all are 0).
// A variable lead (INCR/DECR): δ1 at the lead the cut starts with, δ2 at the lead it has at the
// end of the thread line.
void set_run_in_out(ThreadPlan& plan, double rpm, const LeadLaw& law);

// set_run_in_out for a multi-pass or chained thread, and with `add_run_in` (threading.run_in
// `auto`) plan.run_in_added: the planner then begins every pass run_in before the CL's start.
void plan_run_in_out(ThreadPlan& plan, double rpm, const LeadLaw& law, bool add_run_in);

// How far along the thread line (a chain's first segment) every pass begins before the CL's
// start: the run-in clpost adds with threading.run_in `auto` (plan.run_in_added), else 0.
double added_run_in_along(const ThreadPlan& plan);

// Where the lead is right, along the lead axis (Z, or X for a face-like thread; CL frame).
struct LeadSpan {
  bool known = false;               // the plan's rpm is known (else nothing below is set)
  bool along_z = true;              // the lead axis
  double cut_from = 0, cut_to = 0;  // the stretch every synchronized cut covers, cutting order
  double from = 0, to = 0;          // cut_from + run_in to cut_to − run_out: the lead is right
  bool any = false;                 // from comes before to: some length has the right lead
};

// The span of `plan`: the stretch shared by every pass (from the latest start to the earliest
// end; a single-pass or coupled thread: its path from the first to the last point), less the
// run-in at its start and the run-out at its end. A pull-out is not counted.
LeadSpan lead_span(const ThreadPlan& plan);

// The warning when no length of the thread has the right lead ("" when some has), e.g.
// "run-in 11.930062 and run-out 3.3 at 2000 rpm, lead 3, cover the whole synchronized cut (5
// long): no length of this thread has the right lead; 656 rpm or less leaves one".
std::string no_right_lead_warning(const ThreadPlan& plan, const LeadLaw& law);

}  // namespace clpost
