// Issue-5 conformance matrix: a generated set of thread cases covering the threading reference
// (every OPTION x CUTS/STEP, FINCUT, MULTRD, taper, face, internal, pull-outs, inch and mm) is
// posted with --verify on every shipped machine, and every program must cut its plan pass by pass
// (or the machine refuses the case with the diagnostic named in refusals()). Verify must be
// sensitive: one depth word edited or one pass dropped in a machine's program fails, naming the
// pass and the numbers. The LinuxCNC programs are also run through LinuxCNC's own interpreter
// (rs274): its synchronized moves must be clpost's own simulation of the same program.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>

#include "controls/registry.h"
#include "machine/machine_loader.h"
#include "reader/line_source.h"
#include "simulator/control_sim.h"
#include "support/diagnostics.h"
#include "test_util.h"

namespace clpost::test {
namespace {

namespace fs = std::filesystem;

struct Pt {
  double x = 0, z = 0;  // CL frame: x a radius
};

struct Case {
  std::string name;
  bool inch = false;
  Pt p0, p1, p2;
  std::string params;  // after THREAD/ON,
  std::optional<Pt> p3;
  int rpm = 0;  // 0: 500 (mm) or 300 (inch)
  // What the plan must say (checked in CasesCoverTheReference).
  std::string kind = "turn";
  std::string side = "external";
  int starts = 1;
  bool pullout = false;
  bool linear_pullout = false;  // at 20 or 90 deg to the thread: fed with G1, not threaded
};

// The matrix's machines: every shipped one.
const std::vector<std::string>& machines() {
  static const std::vector<std::string> v = shipped_machine_names();
  return v;
}

// An M20x2.5 external thread 32 mm long (radius 10, Z2 to Z-30, the tool waiting at X15 Z5)
// unless a case says otherwise; DEPTH 1.534 = 0.61343 x 2.5.
Case turn(std::string name, std::string params, const std::string& pitch = "MMPR,2.5") {
  Case c;
  c.name = std::move(name);
  c.p0 = {15, 5};
  c.p1 = {10, 2};
  c.p2 = {10, -30};
  c.params = std::move(params) + "," + pitch;
  return c;
}

// M12x2 internal (bore radius 8.5 ... the crest line of the tap hole), Z2 to Z-25.
Case internal(std::string name, std::string params) {
  Case c;
  c.name = std::move(name);
  c.p0 = {5, 5};
  c.p1 = {8.5, 2};
  c.p2 = {8.5, -25};
  c.params = std::move(params) + ",MMPR,2";
  c.side = "internal";
  return c;
}

// 3/4-16 UNF external, inch: radius 0.375, Z0.1 to Z-1.
Case inch(std::string name, std::string params) {
  Case c;
  c.name = std::move(name);
  c.inch = true;
  c.p0 = {0.6, 0.2};
  c.p1 = {0.375, 0.1};
  c.p2 = {0.375, -1};
  c.params = std::move(params) + ",TPI,16";
  return c;
}

std::vector<Case> make_cases() {
  std::vector<Case> v;
  // Every OPTION with a pass count and with a first step, DEPTH given.
  for (int k = 0; k <= 4; ++k) {
    v.push_back(turn("opt" + std::to_string(k) + "_cuts",
                     "DEPTH,1.534,CUTS,5,OPTION," + std::to_string(k)));
    v.push_back(turn("opt" + std::to_string(k) + "_step",
                     "DEPTH,1.534,STEP,0.5,OPTION," + std::to_string(k)));
  }
  // The other ways of giving the ladder.
  v.push_back(turn("cuts_times_step", "CUTS,4,STEP,0.3835,OPTION,3"));
  v.push_back(turn("cuts_step_pair", "DEPTH,1.534,CUTS,4,0.3835,OPTION,1"));
  v.push_back(turn("couplets", "CUTS,2,0.5,3,0.178,OPTION,0"));
  // FINCUT: finish allowance, spring passes, both, and roughing that stops short of DEPTH.
  v.push_back(turn("fincut_allowance", "DEPTH,1.534,CUTS,5,FINCUT,1,0.1,OPTION,1"));
  v.push_back(turn("fincut_spring", "DEPTH,1.534,CUTS,4,FINCUT,2,OPTION,3"));
  v.push_back(turn("fincut_finish_spring", "DEPTH,1.534,CUTS,4,FINCUT,2,0.05,OPTION,2"));
  v.push_back(turn("fincut_none_at_depth", "DEPTH,1.534,CUTS,4,FINCUT,0,0.1,OPTION,4"));
  // Several starts (each start one pitch earlier, or by spindle angle where the control can).
  {
    Case c = turn("multrd2", "DEPTH,1.534,CUTS,4,OPTION,1,MULTRD,2");
    c.p1 = {10, 6};
    c.starts = 2;
    v.push_back(c);
    Case d = turn("multrd3", "DEPTH,0.92,CUTS,3,OPTION,3,MULTRD,3", "MMPR,1.5");
    d.p0 = {15, 10};
    d.p1 = {10, 9};
    d.starts = 3;
    v.push_back(d);
  }
  // Taper (turn-like), face (lead along X), internal.
  {
    Case c = turn("taper_opt1", "DEPTH,1.227,CUTS,5,OPTION,1", "MMPR,2");
    c.p0 = {16, 5};
    c.p1 = {9, 2};
    c.kind = "taper";
    v.push_back(c);
    Case d = c;
    d.name = "taper_opt0_step";
    d.params = "DEPTH,1.227,STEP,0.4,OPTION,0,MMPR,2";
    v.push_back(d);
    Case f = turn("face", "DEPTH,0.92,CUTS,4,OPTION,0", "MMPR,1.5");
    f.p0 = {30, 5};
    f.p1 = {25, 0};
    f.p2 = {8, 0};
    f.kind = "face";
    v.push_back(f);
    Case g = f;
    g.name = "face_opt3_step";
    g.params = "DEPTH,0.92,STEP,0.3,OPTION,3,MMPR,1.5";
    v.push_back(g);
  }
  v.push_back(internal("internal_opt1", "DEPTH,1.083,CUTS,5,OPTION,1"));
  v.push_back(internal("internal_opt3_step", "DEPTH,1.083,STEP,0.3,OPTION,3"));
  {
    Case c = internal("internal_chamfr", "DEPTH,1.083,CUTS,5,OPTION,0,CHAMFR,1.5");
    c.pullout = true;
    v.push_back(c);
  }
  // Pull-outs: chamfers (45 deg, as high as the thread, negative = run-out, 20 deg = fed with
  // G1), ATANGL (30 deg, and 0: straight out), a third GOTO.
  for (auto [name, params] : std::vector<std::pair<std::string, std::string>>{
           {"chamfr_45", "DEPTH,1.534,CUTS,5,OPTION,1,CHAMFR,2.5"},
           {"chamfr_thread_depth", "DEPTH,1.534,CUTS,5,OPTION,1,CHAMFR,1.534"},
           {"chamfr_negative", "DEPTH,1.534,CUTS,5,OPTION,0,CHAMFR,-3,60"},
           {"chamfr_20deg_linear", "DEPTH,1.534,CUTS,5,OPTION,0,CHAMFR,2,20"},
           {"atangl_30", "DEPTH,1.534,CUTS,5,OPTION,0,ATANGL,30,2"},
           {"atangl_0_straight_out", "DEPTH,1.534,CUTS,5,OPTION,3,ATANGL,0"}}) {
    Case c = turn(name, params);
    c.pullout = true;
    c.linear_pullout = name == "chamfr_20deg_linear" || name == "atangl_0_straight_out";
    v.push_back(c);
  }
  {
    Case c = turn("third_goto", "DEPTH,1.534,CUTS,5,OPTION,1");
    c.p3 = Pt{12.5, -32.5};
    c.pullout = true;
    v.push_back(c);
  }
  // Infeed direction, returns, cutting toward +Z.
  v.push_back(turn("cutang_210", "DEPTH,1.534,CUTS,4,OPTION,3,CUTANG,210"));
  v.push_back(turn("return_3", "DEPTH,1.534,CUTS,5,OPTION,1,RETURN,3"));
  v.push_back(turn("return_to_p0", "DEPTH,1.534,CUTS,5,OPTION,1,RETURN"));
  {
    Case c = turn("toward_plus_z", "DEPTH,1.534,CUTS,5,OPTION,1");
    c.p0 = {15, -35};
    c.p1 = {10, -30};
    c.p2 = {10, 2};
    v.push_back(c);
  }
  // Inch.
  v.push_back(inch("inch_opt1_fincut", "DEPTH,0.0384,CUTS,4,FINCUT,1,0.004,OPTION,1"));
  v.push_back(inch("inch_opt0_step", "DEPTH,0.0384,STEP,0.012,OPTION,0"));
  v.push_back(inch("inch_opt2", "DEPTH,0.0384,CUTS,5,OPTION,2"));
  v.push_back(inch("inch_cutang", "DEPTH,0.0384,CUTS,4,OPTION,0,CUTANG,210"));
  {
    Case c = inch("inch_chamfr", "DEPTH,0.0384,CUTS,5,OPTION,3,CHAMFR,0.06");
    c.pullout = true;
    v.push_back(c);
  }
  // Refused by some machines (refusals()): a variable lead, a feed above a machine's limit.
  v.push_back(turn("variable_lead", "DEPTH,1.534,CUTS,5,OPTION,1,INCR,0.01"));
  {
    Case c = turn("fast_spindle", "DEPTH,1.534,CUTS,5,OPTION,1");
    c.rpm = 2200;  // 2.5 x 2200 = 5500 mm/min
    v.push_back(c);
  }
  return v;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> v = make_cases();
  return v;
}

const Case& case_named(const std::string& name) {
  for (const Case& c : cases())
    if (c.name == name) return c;
  ADD_FAILURE() << "no case " << name;
  return cases().front();
}

constexpr int kThreadLine = 11;  // THREAD/ON in cl_text

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string cl_text(const Case& c) {
  const Pt safe = c.inch ? Pt{2, 2} : Pt{40, 40};
  const int rpm = c.rpm ? c.rpm : c.inch ? 300 : 500;
  std::ostringstream s;
  s << "PARTNO/" << c.name << "\n"                                    // 1
    << (c.inch ? "UNITS/INCHES\n" : "UNITS/MM\n")                     // 2
    << "LOADTL/1\n"                                                   // 3
    << "SPINDL/" << rpm << ",RPM,CLW\n"                               // 4
    << "COOLNT/FLOOD\n"                                               // 5
    << (c.inch ? "FEDRAT/0.008,IPR\n" : "FEDRAT/0.2,MMPR\n")          // 6
    << "RAPID\nGOTO/" << num(safe.x) << ",0," << num(safe.z) << "\n"  // 7, 8
    << "RAPID\nGOTO/" << num(c.p0.x) << ",0," << num(c.p0.z) << "\n"  // 9, 10
    << "THREAD/ON," << c.params << "\n"                               // 11
    << "GOTO/" << num(c.p1.x) << ",0," << num(c.p1.z) << "\n"
    << "GOTO/" << num(c.p2.x) << ",0," << num(c.p2.z) << "\n";
  if (c.p3) s << "GOTO/" << num(c.p3->x) << ",0," << num(c.p3->z) << "\n";
  s << "THREAD/OFF\nRAPID\nGOTO/" << num(safe.x) << ",0," << num(safe.z)
    << "\nCOOLNT/OFF\nSPINDL/OFF\nFINI\n";
  return s.str();
}

// A machine's legitimate refusal of a case: clpost -m M --verify exits 1, writes nothing, and
// stderr has this error at the THREAD/ON line.
struct Refusal {
  std::string machine, case_name, message;
  int line = kThreadLine;  // the CL line of the error
};

std::vector<Refusal> refusals() {
  std::vector<Refusal> v;
  for (const std::string& m : machines()) {
    if (shipped_machine(m).variable_lead) continue;  // G34: cut, and verified
    v.push_back({m, "variable_lead",
                 "error: variable lead (INCR 0.01 per revolution, CL line " +
                     std::to_string(kThreadLine) + ") cannot be cut on machine '" + m +
                     "': it does not declare variable-lead threading (G34/G35)"});
  }
  // linuxcnc-lathe-c is linuxcnc-lathe with C and a live tool: the same feed limit.
  for (const char* m : {"linuxcnc-lathe", "linuxcnc-lathe-c"})
    v.push_back({m, "fast_spindle",
                 std::string("error: thread feed too fast for machine '") + m +
                     "': lead 2.5 x 2200 rpm = 5500 per minute, above its maximum feed 5000"});
  // A control that reads a program in one unit (HEIDENHAIN DIN) on a machine in mm: the inch
  // cases' UNITS/INCHES (CL line 2) is an error.
  for (const std::string& m : machines()) {
    const Machine machine = shipped_machine(m);
    if (!machine.control || !machine.control->one_unit_per_program) continue;
    for (const Case& c : cases())
      if (c.inch != (machine.default_units == "in"))
        v.push_back({m, c.name,
                     "error: machine '" + m + "' (" + std::string(machine.control->name) +
                         ") reads the whole program in " + machine.default_units,
                     2});
  }
  return v;
}

const Refusal* refusal_of(const std::string& machine, const std::string& case_name) {
  static const std::vector<Refusal> v = refusals();
  for (const Refusal& r : v)
    if (r.machine == machine && r.case_name == case_name) return &r;
  return nullptr;
}

// The refusal's diagnostic is on a line of `err` that names the case's THREAD/ON line.
bool has_refusal(const std::string& err, const Refusal& r) {
  std::istringstream in(err);
  std::string line;
  const std::string where = r.case_name + ".cl:" + std::to_string(r.line) + ":";
  while (std::getline(in, line))
    if (line.find(where) != std::string::npos && line.find(r.message) != std::string::npos)
      return true;
  return false;
}

// One pass of `clpost plan --format json`.
struct PlanPass {
  int n = 0, start = 0;
  double depth = 0, shift = 0;
  Pt from, to;
};

std::vector<PlanPass> plan_passes(const std::string& json) {
  static const std::regex re(
      R"re(\{"n": (\d+), "start": (\d+), "depth": ([-0-9.e]+), "kind": "\w+", "shift": ([-0-9.e]+), "from": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\}, "to": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\}\})re");
  std::vector<PlanPass> out;
  for (auto it = std::sregex_iterator(json.begin(), json.end(), re); it != std::sregex_iterator();
       ++it) {
    const std::smatch& m = *it;
    PlanPass p;
    p.n = std::stoi(m[1]);
    p.start = std::stoi(m[2]);
    p.depth = std::stod(m[3]);
    p.shift = std::stod(m[4]);
    p.from = {std::stod(m[5]), std::stod(m[6])};
    p.to = {std::stod(m[7]), std::stod(m[8])};
    out.push_back(p);
  }
  return out;
}

std::string json_string(const std::string& json, const std::string& key) {
  std::smatch m;
  if (std::regex_search(json, m, std::regex("\"" + key + "\": \"([^\"]*)\""))) return m[1];
  return "";
}

double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  if (std::regex_search(json, m, std::regex("\"" + key + "\": ([-0-9.e]+)")))
    return std::stod(m[1]);
  return NAN;
}

// A scratch directory with every case's CL file, removed at the end of the test.
struct Workspace {
  std::string dir = temp_dir();
  Workspace() {
    for (const Case& c : cases()) write_file(cl(c), cl_text(c));
  }
  ~Workspace() { fs::remove_all(dir); }
  std::string cl(const Case& c) const { return dir + "/" + c.name + ".cl"; }
  std::string out(const Case& c, const std::string& machine) const {
    return dir + "/" + c.name + "." + machine + ".nc";
  }
};

std::string plan_json(const Workspace& w, const Case& c, const std::string& machine) {
  RunResult r =
      run(quote(clpost_bin()) + " plan --format json -m " + machine + " " + quote(w.cl(c)));
  EXPECT_EQ(r.exit_code, 0) << c.name << ": " << r.err;
  return r.out;
}

RunResult post_verified(const Workspace& w, const Case& c, const std::string& machine) {
  return run(quote(clpost_bin()) + " -m " + machine + " --verify -o " + quote(w.out(c, machine)) +
             " " + quote(w.cl(c)));
}

RunResult verify(const std::string& machine, const std::string& program, const std::string& cl) {
  return run(quote(clpost_bin()) + " verify -m " + machine + " " + quote(program) + " --cl " +
             quote(cl));
}

const std::string kOk = "ok: every pass is cut as planned, within ";

// ---------------------------------------------------------------------------------------------

// The matrix runs on every machine `clpost machines` lists, and the cases say (and the plans
// confirm) what they cover.
TEST(Conformance, MatrixCoversEveryShippedMachine) {
  RunResult r = run(quote(clpost_bin()) + " machines");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::set<std::string> listed;
  std::istringstream in(r.out);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream l(line);
    std::string name;
    if (l >> name) listed.insert(name);
  }
  ASSERT_FALSE(listed.empty()) << r.out;
  EXPECT_EQ(listed, std::set<std::string>(machines().begin(), machines().end()))
      << "the tests' listing of the shipped machines (shipped_machine_names) is not clpost's";
}

// A shipped machine that plans every case: one that cuts variable leads too (G34/G35).
std::string machine_planning_every_case() {
  for (const std::string& m : machines())
    if (shipped_machine(m).variable_lead) return m;
  ADD_FAILURE() << "no shipped machine declares variable-lead threading (G34/G35)";
  return "";
}

TEST(Conformance, CasesCoverTheReference) {
  Workspace w;
  ASSERT_GE(cases().size(), 30u);
  ASSERT_LE(cases().size(), 60u);
  std::set<std::string> names;
  std::map<std::string, int> seen;  // feature -> cases
  const std::string planner = machine_planning_every_case();
  ASSERT_NE(planner, "");
  for (const Case& c : cases()) {
    EXPECT_TRUE(names.insert(c.name).second) << "two cases named " << c.name;
    const std::string json = plan_json(w, c, planner);
    SCOPED_TRACE(c.name + "\n" + json);
    EXPECT_EQ(json_string(json, "units"), c.inch ? "in" : "mm");
    EXPECT_EQ(json_string(json, "form"), "multi");
    EXPECT_EQ(json_number(json, "line"), kThreadLine);
    EXPECT_EQ(json_string(json, "kind"), c.kind);
    EXPECT_EQ(json_string(json, "side"), c.side);
    EXPECT_EQ(json_number(json, "starts"), c.starts);
    EXPECT_EQ(json.find("\"pullout\": null") == std::string::npos, c.pullout);
    const std::vector<PlanPass> passes = plan_passes(json);
    ASSERT_FALSE(passes.empty());
    // Every pass of every start, the last one at DEPTH (or DEPTH - allowance with FINCUT,0,f).
    const double depth = json_number(json, "depth");
    const bool short_of_depth = c.params.find("FINCUT,0,") != std::string::npos;
    EXPECT_NEAR(passes.back().depth, short_of_depth ? depth - 0.1 : depth, 1e-6);
    EXPECT_EQ(passes.size() % c.starts, 0u);
    const double option = json_number(json, "option");
    const bool by_step = c.params.find("STEP,") != std::string::npos;
    const bool by_cuts = c.params.find("CUTS,") != std::string::npos;
    if (by_cuts && !by_step) ++seen["option " + num(option) + " CUTS"];
    if (by_step && !by_cuts) ++seen["option " + num(option) + " STEP"];
    if (c.params.find("FINCUT") != std::string::npos) ++seen["FINCUT"];
    if (json.find("\"kind\": \"spring\"") != std::string::npos) ++seen["spring pass"];
    if (json.find("\"kind\": \"finish\"") != std::string::npos) ++seen["finish pass"];
    if (c.starts > 1) ++seen["MULTRD " + std::to_string(c.starts)];
    ++seen[c.kind];
    ++seen[c.side];
    ++seen[c.inch ? "inch" : "mm"];
    if (c.params.find("CHAMFR,") != std::string::npos) ++seen["CHAMFR"];
    if (c.params.find("ATANGL,") != std::string::npos) ++seen["ATANGL"];
    if (c.params.find("ATANGL,0") != std::string::npos) {
      // Straight out: the pull-out is at right angles to the thread (along X on a turn thread).
      std::smatch m;
      ASSERT_TRUE(std::regex_search(
          json, m, std::regex(R"re("pullout": \{"x": ([-0-9.e]+), "z": ([-0-9.e]+)\})re")));
      EXPECT_GT(std::stod(m[1]), 0);
      EXPECT_EQ(std::stod(m[2]), 0);
      ++seen["straight-out pull-out"];
    }
    if (c.p3) ++seen["third GOTO"];
    if (c.params.find("CUTANG") != std::string::npos) ++seen["CUTANG"];
    if (c.params.find("RETURN") != std::string::npos) ++seen["RETURN"];
  }
  for (int k = 0; k <= 4; ++k) {
    EXPECT_GE(seen["option " + std::to_string(k) + " CUTS"], 1) << "OPTION " << k;
    EXPECT_GE(seen["option " + std::to_string(k) + " STEP"], 1) << "OPTION " << k;
  }
  for (const char* f : {"FINCUT", "spring pass", "finish pass", "MULTRD 2", "MULTRD 3", "turn",
                        "taper", "face", "external", "internal", "inch", "mm", "CHAMFR", "ATANGL",
                        "straight-out pull-out", "third GOTO", "CUTANG", "RETURN"})
    EXPECT_GE(seen[f], 1) << f;
}

class ConformanceMatrix : public ::testing::TestWithParam<std::string> {};

// Every case on this machine: posted with --verify, the program cuts the plan (and the report
// counts the plan's passes), or the machine refuses it as refusals() says. A few are verified a
// second time through `clpost verify` on the written program.
TEST_P(ConformanceMatrix, EveryCaseVerifies) {
  const std::string machine = GetParam();
  Workspace w;
  const std::set<std::string> also_subcommand = {"opt1_cuts", "multrd2", "taper_opt1",
                                                 "face_opt3_step", "inch_opt1_fincut"};
  int verified = 0, refused = 0, subcommand = 0;
  for (const Case& c : cases()) {
    SCOPED_TRACE(machine + " x " + c.name);
    RunResult r = post_verified(w, c, machine);
    if (const Refusal* ref = refusal_of(machine, c.name)) {
      EXPECT_EQ(r.exit_code, 1) << r.err;
      EXPECT_TRUE(has_refusal(r.err, *ref)) << ref->message << "\n" << r.err;
      EXPECT_EQ(r.err.find(kOk), std::string::npos) << r.err;
      EXPECT_FALSE(file_exists(w.out(c, machine)));
      ++refused;
      continue;
    }
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("\n" + kOk), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("error:"), std::string::npos) << r.err;
    ASSERT_TRUE(file_exists(w.out(c, machine))) << r.err;
    const size_t planned = plan_passes(plan_json(w, c, machine)).size();
    const std::string counts = ": 1 threads, " + std::to_string(planned) + " passes planned, " +
                               std::to_string(planned) + " cut\n";
    EXPECT_NE(r.err.find(counts), std::string::npos) << counts << r.err;
    if (r.exit_code == 0) ++verified;
    if (also_subcommand.count(c.name)) {
      RunResult v = verify(machine, w.out(c, machine), w.cl(c));
      EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
      EXPECT_NE(v.out.find(counts), std::string::npos) << v.out;
      EXPECT_NE(v.out.find("\n" + kOk), std::string::npos) << v.out;
      EXPECT_EQ(v.err, "");
      ++subcommand;
    }
  }
  size_t want_refused = 0;
  for (const Refusal& r : refusals()) want_refused += r.machine == machine;
  EXPECT_EQ(refused, static_cast<int>(want_refused));
  EXPECT_EQ(verified + refused, static_cast<int>(cases().size()));
  int want_subcommand = 0;
  for (const std::string& name : also_subcommand) want_subcommand += !refusal_of(machine, name);
  EXPECT_EQ(subcommand, want_subcommand);
  std::printf("%s: %d cases verify, %d refused as expected\n", machine.c_str(), verified, refused);
}

// The number of a word in an NC line as written (its text), and a copy with it changed by `by`
// and written with as many decimals.
std::string shifted(const std::string& text, double by) {
  const size_t dot = text.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(text.size() - dot - 1);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", std::max(decimals, 1), std::stod(text) + by);
  return buf;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string l;
  while (std::getline(in, l)) out.push_back(l);
  return out;
}

std::string join(const std::vector<std::string>& lines) {
  std::string s;
  for (const std::string& l : lines) s += l + "\n";
  return s;
}

// The line without its comment ((...), [...], ; ...).
std::string code_of(const std::string& line) {
  std::string s;
  int depth = 0;
  for (char ch : line) {
    if (ch == ';') break;
    if (ch == '(' || ch == '[') ++depth;
    if (depth == 0) s += ch;
    if ((ch == ')' || ch == ']') && depth > 0) --depth;
  }
  return s;
}

// The line (index) whose X word is the diameter `x` (within half a least increment of 0.001),
// and the word's number as written. Exactly one such line is expected.
std::pair<int, std::string> line_with_x(const std::vector<std::string>& lines, double x) {
  static const std::regex x_re(R"re(X(-?[0-9]+\.?[0-9]*))re");
  std::pair<int, std::string> found{-1, ""};
  int count = 0;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string code = code_of(lines[i]);
    for (auto it = std::sregex_iterator(code.begin(), code.end(), x_re);
         it != std::sregex_iterator(); ++it)
      if (std::fabs(std::stod((*it)[1]) - x) < 0.0015) {
        found = {static_cast<int>(i), (*it)[1]};
        ++count;
      }
  }
  EXPECT_EQ(count, 1) << "X" << x << " in\n" << join(lines);
  return found;
}

// opt0_cuts is a loop (G33 chain, G92) or an emulation on every machine (no control's cycle
// has OPTION 0's law); its pass 3 is infed to X = 2 (10 - depth 3).
struct LoopProgram {
  std::string cl, program, json;
  std::vector<PlanPass> passes;
  std::vector<std::string> lines;
  int pass3_line = -1;
  std::string pass3_x;
};

LoopProgram loop_program(const Workspace& w, const std::string& machine) {
  const Case& c = case_named("opt0_cuts");
  LoopProgram p;
  p.cl = w.cl(c);
  p.json = plan_json(w, c, machine);
  p.passes = plan_passes(p.json);
  RunResult r = post_verified(w, c, machine);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  p.program = w.out(c, machine);
  p.lines = lines_of(read_file(p.program));
  EXPECT_EQ(p.passes.size(), 5u);
  if (p.passes.size() != 5u) return p;
  std::tie(p.pass3_line, p.pass3_x) = line_with_x(p.lines, 2 * (c.p1.x - p.passes[2].depth));
  return p;
}

// A number in "pass 3: depth A, plan B" and the like.
struct Reported {
  int pass = 0;
  double value = 0, plan = 0, tolerance = 0;
};

std::vector<Reported> reported(const std::string& report, const std::string& field) {
  std::regex re("pass (\\d+): " + field +
                " ([-0-9.]+), plan ([-0-9.]+) \\(tolerance ([-0-9.e]+)\\)");
  std::vector<Reported> out;
  for (auto it = std::sregex_iterator(report.begin(), report.end(), re);
       it != std::sregex_iterator(); ++it)
    out.push_back(
        {std::stoi((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])});
  return out;
}

// The infeed of pass 3 taken 0.05 deeper (X 0.1 less on the diameter): verify names pass 3, its
// depth in the program and in the plan, and nothing else.
TEST_P(ConformanceMatrix, LoopInfeedEditIsReported) {
  const std::string machine = GetParam();
  Workspace w;
  LoopProgram p = loop_program(w, machine);
  ASSERT_GE(p.pass3_line, 0);
  std::vector<std::string> lines = p.lines;
  std::string& l = lines[static_cast<size_t>(p.pass3_line)];
  const std::string edited = shifted(p.pass3_x, -0.1);
  l.replace(l.find("X" + p.pass3_x), p.pass3_x.size() + 1, "X" + edited);
  const std::string nc = w.dir + "/edited." + machine + ".nc";
  write_file(nc, join(lines));
  RunResult r = verify(machine, nc, p.cl);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const std::vector<Reported> got = reported(r.out, "depth");
  ASSERT_EQ(got.size(), 1u) << l << "\n" << r.out << r.err;
  EXPECT_EQ(got[0].pass, 3);
  EXPECT_NEAR(got[0].plan, p.passes[2].depth, 1e-4);
  EXPECT_NEAR(got[0].value, 10 - std::stod(edited) / 2, 1e-4) << r.out;
  EXPECT_NEAR(got[0].value - got[0].plan, 0.05, 0.0006) << r.out;
  EXPECT_NE(r.out.find("\nFAILED: 1 difference beyond "), std::string::npos) << r.out;
  // The diagnostic points at pass 3's blocks: the edited one or the cut right after it.
  std::smatch at;
  ASSERT_TRUE(std::regex_search(
      r.err, at, std::regex(R"re(:(\d+):1: error: thread at [^\n]*: pass 3: depth )re")))
      << r.err;
  EXPECT_GE(std::stoi(at[1]), p.pass3_line + 1) << r.err;
  EXPECT_LE(std::stoi(at[1]), p.pass3_line + 2) << r.err;
}

// Pass 3 left out (its blocks between the "pass 3" and "pass 4" comments, or its one G92 block):
// verify says pass 3 is not cut, with its depth, and nothing else.
TEST_P(ConformanceMatrix, DroppedPassIsReported) {
  const std::string machine = GetParam();
  Workspace w;
  LoopProgram p = loop_program(w, machine);
  ASSERT_GE(p.pass3_line, 0);
  int first = p.pass3_line, last = p.pass3_line;  // [first, last]
  auto is_pass_comment = [](const std::string& l, int n) {
    std::string low;
    for (char ch : l) low += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return low.find("pass " + std::to_string(n) + " depth") != std::string::npos;
  };
  for (int i = 0; i < static_cast<int>(p.lines.size()); ++i)
    if (is_pass_comment(p.lines[static_cast<size_t>(i)], 3)) first = i;
  if (first != p.pass3_line) {
    last = first + 1;
    while (last < static_cast<int>(p.lines.size()) &&
           !is_pass_comment(p.lines[static_cast<size_t>(last)], 4))
      ++last;
    --last;
    ASSERT_GE(last, p.pass3_line);
  }
  std::vector<std::string> lines = p.lines;
  lines.erase(lines.begin() + first, lines.begin() + last + 1);
  const std::string nc = w.dir + "/dropped." + machine + ".nc";
  write_file(nc, join(lines));
  RunResult r = verify(machine, nc, p.cl);
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(
      r.out, m,
      std::regex(
          R"re(pass (\d+) \(depth ([0-9.]+), from X([-0-9.]+) Z([-0-9.]+)\) is not cut by the program)re")))
      << r.out << r.err;
  EXPECT_EQ(std::stoi(m[1]), 3);
  EXPECT_NEAR(std::stod(m[2]), p.passes[2].depth, 1e-4);
  EXPECT_NEAR(std::stod(m[3]), 2 * p.passes[2].from.x, 1e-4);
  EXPECT_NEAR(std::stod(m[4]), p.passes[2].from.z, 1e-4);
  EXPECT_NE(r.out.find("\nFAILED: 1 difference beyond "), std::string::npos)
      << "lines " << first + 1 << "-" << last + 1 << " dropped\n"
      << r.out;
  EXPECT_NE(r.out.find("5 passes planned, 4 cut"), std::string::npos) << r.out;
}

INSTANTIATE_TEST_SUITE_P(Machines, ConformanceMatrix, ::testing::ValuesIn(machines()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

// A depth word of a control's own cycle, edited in opt1_cuts (a cycle on every machine that
// threads with its control's cycle): every pass moves, and verify names each with its depth.
// `deeper` is how the edit moves pass i's depth d (plan) to the program's: by 0.1 everywhere when
// the thread's bottom word moves, or in proportion when the total depth word grows by 0.1 (these
// laws scale with it).
struct CycleEdit {
  std::string_view thread_cycle;  // the machine's threading.cycle
  std::string cycle;              // the word that must be in the program once
  std::regex word;                // group 1: the number to change
  double by;                      // added to it
  bool proportional;              // false: every depth + 0.1; true: every depth x (D + 0.1) / D
};

std::vector<CycleEdit> cycle_edits() {
  return {
      // Fanuc's second G76 block: X is the thread bottom (diameter); P the height stays, so the
      // crest moves with it.
      {"fanuc_g76", "G76 X", std::regex(R"re(G76 X([0-9.]+) Z)re"), -0.2, false},
      {"haas_g76", "G76 X", std::regex(R"re(G76 X([0-9.]+) Z)re"), -0.2, false},
      // LinuxCNC: I is the crest's offset from the drive line (diameter mode).
      {"linuxcnc_g76", "G76 P", std::regex(R"re(G76 P[0-9.]+ Z[-0-9.]+ I(-[0-9.]+) )re"), -0.2,
       false},
      // CYCLE99's 7th argument TDEP; HEIDENHAIN G31 U: the thread depth.
      {"cycle99", "CYCLE99(", std::regex(R"re(CYCLE99\((?:[^,]+, ){6}([0-9.]+), )re"), 0.1, true},
      {"heidenhain_g31", "G31 F", std::regex(R"re(G31 F[0-9.]+ U([0-9.]+) )re"), 0.1, true},
  };
}

// The shipped machines that thread with their control's own cycle.
std::vector<std::string> cycle_machines() {
  std::vector<std::string> v;
  for (const std::string& m : machines())
    if (shipped_machine(m).thread_strategy == ThreadStrategy::kCycle) v.push_back(m);
  return v;
}

class CycleDepthWord : public ::testing::TestWithParam<std::string> {};

TEST_P(CycleDepthWord, EditIsReportedPassByPass) {
  const std::string machine = GetParam();
  const Machine shipped = shipped_machine(machine);
  const std::string_view thread_cycle = shipped.control ? shipped.control->cycle : "none";
  const std::vector<CycleEdit> edits = cycle_edits();
  const auto edit = std::find_if(edits.begin(), edits.end(), [&](const CycleEdit& e) {
    return e.thread_cycle == thread_cycle;
  });
  ASSERT_NE(edit, edits.end()) << "machine " << machine
                               << " threads with a cycle that has no depth word in cycle_edits(): "
                                  "add one";
  const CycleEdit& e = *edit;
  Workspace w;
  const Case& c = case_named("opt1_cuts");
  const std::string json = plan_json(w, c, machine);
  const std::vector<PlanPass> passes = plan_passes(json);
  ASSERT_EQ(passes.size(), 5u);
  RunResult post = post_verified(w, c, machine);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  std::string nc = read_file(w.out(c, machine));
  ASSERT_EQ(nc.find(e.cycle), nc.rfind(e.cycle)) << nc;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(nc, m, e.word)) << nc;
  const std::string before = m[1];
  const std::string after = shifted(before, e.by);
  const size_t at = static_cast<size_t>(m.position(1));
  nc.replace(at, before.size(), after);
  const std::string edited = w.dir + "/edited.nc";
  write_file(edited, nc);
  RunResult r = verify(machine, edited, w.cl(c));
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const double depth = json_number(json, "depth");
  std::vector<Reported> got = reported(r.out, "depth");
  ASSERT_EQ(got.size(), 5u) << before << " -> " << after << "\n" << r.out << r.err;
  for (size_t i = 0; i < got.size(); ++i) {
    SCOPED_TRACE(r.out);
    EXPECT_EQ(got[i].pass, static_cast<int>(i + 1));
    EXPECT_NEAR(got[i].plan, passes[i].depth, 1e-4);
    const double want =
        e.proportional ? passes[i].depth * (depth + 0.1) / depth : passes[i].depth + 0.1;
    // The control's law rounds its words (Fanuc: depths in micrometres): within its tolerance.
    EXPECT_NEAR(got[i].value, want, got[i].tolerance + 1e-4) << "pass " << i + 1;
    EXPECT_GT(std::fabs(got[i].value - got[i].plan), got[i].tolerance);
  }
  EXPECT_NE(r.out.find("\nFAILED: 5 differences beyond "), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("pass 5: depth "), std::string::npos) << r.err;
}

INSTANTIATE_TEST_SUITE_P(Machines, CycleDepthWord, ::testing::ValuesIn(cycle_machines()),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           std::string n = i.param;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

// LinuxCNC: rs274's synchronized moves are clpost's own simulation of the same program, cut by
// cut: every synchronized move of every pass (the thread, then each threaded pull-out move) starts
// and ends at the same point within 0.001 mm.
class ConformanceRs274 : public ::testing::TestWithParam<std::string> {};

TEST_P(ConformanceRs274, SimulationAgreesWithRs274) {
  if (!rs274_available())
    GTEST_SKIP() << "rs274 not installed (apt-get install linuxcnc-uspace): skipped";
  const Case& c = case_named(GetParam());
  const std::string machine = "linuxcnc-lathe";
  Workspace w;
  RunResult post = post_verified(w, c, machine);
  ASSERT_EQ(post.exit_code, 0) << post.err;
  const std::string ngc = w.out(c, machine);
  RunResult r = run_rs274(w.dir, ngc);
  ASSERT_EQ(r.exit_code, 0) << "rs274: " << r.err << "\n" << read_file(ngc);
  const std::vector<CanonSegment> canon = rs274_synced_moves(r.out);

  Machine m;
  std::string errors;
  ASSERT_TRUE(load_machine(machine, {source_dir()}, {}, shipped_controls(), m, errors)) << errors;
  const std::string text = read_file(ngc);
  reader::LineSource src{std::string_view(text)};
  Diagnostics diags(ngc);
  Simulation sim;
  ASSERT_TRUE(simulate_nc(src, m, diags, sim)) << diags.render_all();
  std::vector<CanonSegment> ours;
  for (const NcCut& cut : sim.cuts) {
    Vec2 from = cut.from;
    for (const Vec2& to : cut.chain) {
      ours.push_back({{from.x, from.z}, {to.x, to.z}});
      from = to;
    }
  }
  const size_t planned = plan_passes(plan_json(w, c, machine)).size();
  EXPECT_EQ(sim.cuts.size(), planned);
  // A threaded pull-out is a second synchronized move of every pass.
  EXPECT_EQ(ours.size(), planned * (c.pullout && !c.linear_pullout ? 2 : 1));
  ASSERT_EQ(canon.size(), ours.size()) << text << "\n" << r.out;
  // rs274 prints 4 decimals: in an inch program half its last digit is added to 0.001 mm.
  const double tol = c.inch ? 0.001 / 25.4 + 0.00005 : 0.001;
  for (size_t i = 0; i < ours.size(); ++i) {
    SCOPED_TRACE("synchronized move " + std::to_string(i + 1) + " of " +
                 std::to_string(ours.size()));
    EXPECT_NEAR(canon[i].from.x, ours[i].from.x, tol);
    EXPECT_NEAR(canon[i].from.z, ours[i].from.z, tol);
    EXPECT_NEAR(canon[i].to.x, ours[i].to.x, tol);
    EXPECT_NEAR(canon[i].to.z, ours[i].to.z, tol);
  }
}

// Every case linuxcnc-lathe does not refuse.
std::vector<std::string> linuxcnc_case_names() {
  std::vector<std::string> v;
  for (const Case& c : cases())
    if (refusal_of("linuxcnc-lathe", c.name) == nullptr) v.push_back(c.name);
  return v;
}

INSTANTIATE_TEST_SUITE_P(Cases, ConformanceRs274, ::testing::ValuesIn(linuxcnc_case_names()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });

}  // namespace
}  // namespace clpost::test
