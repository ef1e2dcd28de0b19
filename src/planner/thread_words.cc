#include "planner/thread_words.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "support/number_text.h"

namespace clpost {

void PitchWords::apply_to(PitchSpec& spec) const {
  if (value_given) {
    spec.set = true;
    spec.pitch = pitch;
    spec.from_tpi = from_tpi;
    spec.tpi = tpi;
    spec.loc = value_loc;
  }
  if (starts_given) {
    spec.starts = starts;
    spec.starts_loc = starts_loc;
  }
  if (change_given) {
    spec.lead_change = lead_change;
    spec.lead_change_loc = change_loc;
  }
}

namespace {

constexpr double kMmPerInch = 25.4;

// Walks the arguments of one statement and reports errors at them.
class Args {
 public:
  Args(const Statement& st, size_t first, Diagnostics& diags) : st_(st), i_(first), diags_(diags) {}

  bool done() const { return i_ >= st_.args.size(); }
  const Arg& peek() const { return st_.args[i_]; }
  bool peek_number() const { return !done() && peek().is_number(); }
  bool peek_word() const { return !done() && peek().is_word(); }
  const Arg& take() { return st_.args[i_++]; }
  void skip_numbers() {
    while (peek_number()) ++i_;
  }
  bool ok() const { return ok_; }

  void error(SourceLoc loc, std::string message) {
    diags_.error(loc, st_.line_text(loc.line), std::move(message));
    ok_ = false;
  }

  // What stands at the cursor, for "found ..." in messages.
  std::string found() const { return describe_arg(st_.args, i_); }
  // The same for `a`, an argument already taken.
  std::string shown(const Arg& a) const { return describe_arg(st_, a); }

  // Takes the number after `key`, or reports "expected <what> after KEY".
  bool number(const Arg& key, std::string_view what, double& v) {
    if (!peek_number()) {
      error(key.loc, fmt::format("expected {} after {}, found {}", what, key.text, found()));
      return false;
    }
    v = take().number;
    return true;
  }

  // After a keyword's values: a further number is an error.
  void no_more_numbers(const Arg& key, std::string_view form) {
    if (!peek_number()) return;
    const Arg& extra = peek();
    error(extra.loc, fmt::format("unexpected number {} after {}: {} takes {}", extra.text, key.text,
                                 key.text, form));
    skip_numbers();
  }

  // "first at column 12" or "first at line 4, column 12".
  std::string where(SourceLoc first, SourceLoc now) const {
    if (first.line == now.line) return fmt::format("column {}", first.col);
    return fmt::format("line {}, column {}", first.line, first.col);
  }

 private:
  const Statement& st_;
  size_t i_;
  Diagnostics& diags_;
  bool ok_ = true;
};

bool is_whole(double v) {
  return std::isfinite(v) && std::fabs(v - std::round(v)) < 1e-9;
}

bool is_pitch_unit(const Arg& a) {
  return a.is("TPI") || a.is("IPR") || a.is("MMPR") || a.is("PERREV");
}

std::string_view unit_what(std::string_view unit) {
  if (unit == "TPI") return "the threads per inch";
  if (unit == "IPR") return "the pitch in inches";
  if (unit == "MMPR") return "the pitch in mm";
  if (unit == "PERREV") return "the pitch in CL units";
  return "the threads per CL unit";
}

// Sets the pitch part of `pw` from `v` given in `unit` ("" for the unqualified PITCH/ value).
void set_pitch(std::string_view unit, double v, LengthUnit cl_units, SourceLoc loc,
               PitchWords& pw) {
  const bool inch = cl_units == LengthUnit::kInch;
  pw.value_given = true;
  pw.value_loc = loc;
  pw.from_tpi = false;
  pw.tpi = 0;
  if (unit == "TPI") {
    pw.pitch = inch ? 1 / v : kMmPerInch / v;
    pw.from_tpi = true;
    pw.tpi = v;
  } else if (unit == "IPR") {
    pw.pitch = inch ? v : v * kMmPerInch;
  } else if (unit == "MMPR") {
    pw.pitch = inch ? v / kMmPerInch : v;
  } else if (unit == "PERREV") {
    pw.pitch = v;
  } else {  // threads per CL unit
    pw.pitch = 1 / v;
    if (inch) {
      pw.from_tpi = true;
      pw.tpi = v;
    }
  }
}

// A pitch value must be positive (and finite).
bool check_pitch_value(Args& a, const Arg& key, double v) {
  if (std::isfinite(v) && v > 0) return true;
  a.error(key.loc, fmt::format("{} must be positive; got {}", key.text, num_text(v)));
  return false;
}

// The value part was given before on this statement: error.
bool check_pitch_once(Args& a, const Arg& key, const PitchWords& pw, std::string_view first_word) {
  if (!pw.value_given) return true;
  a.error(key.loc, fmt::format("{}: the pitch is already given by {} at {}", key.text, first_word,
                               a.where(pw.value_loc, key.loc)));
  return false;
}

// Parses one pitch couplet whose keyword `key` has just been taken (TPI|IPR|MMPR|PERREV,v,
// MULTRD,n, INCR|DECR,dv). `first_word` remembers which word gave the pitch value.
void pitch_couplet(Args& a, const Arg& key, LengthUnit cl_units, PitchWords& pw,
                   std::string& first_word) {
  double v = 0;
  if (is_pitch_unit(key)) {
    if (!a.number(key, unit_what(key.text), v)) return;
    if (check_pitch_value(a, key, v) && check_pitch_once(a, key, pw, first_word)) {
      set_pitch(key.text, v, cl_units, key.loc, pw);
      first_word = key.text;
    }
    a.no_more_numbers(key, fmt::format("one value ({},v)", key.text));
  } else if (key.is("MULTRD")) {
    if (!a.number(key, "the number of starts", v)) return;
    if (pw.starts_given) {
      a.error(key.loc,
              fmt::format("MULTRD is given twice (first at {})", a.where(pw.starts_loc, key.loc)));
    } else if (!is_whole(v) || v < 1) {
      a.error(key.loc,
              fmt::format("MULTRD must be a positive whole number of starts; got {}", num_text(v)));
    } else if (v > kMaxStarts) {
      a.error(key.loc, fmt::format("MULTRD {} is more than the {} starts a thread may have",
                                   num_text(v), kMaxStarts));
    } else {
      pw.starts_given = true;
      pw.starts = static_cast<int>(std::lround(v));
      pw.starts_loc = key.loc;
    }
    a.no_more_numbers(key, "one value (MULTRD,n)");
  } else {  // INCR / DECR
    if (!a.number(key, "the lead change per revolution", v)) return;
    if (pw.change_given) {
      a.error(key.loc, fmt::format("{}: the lead change is already given at {}", key.text,
                                   a.where(pw.change_loc, key.loc)));
    } else if (!std::isfinite(v) || v < 0) {
      a.error(key.loc, fmt::format("{} takes the size of the lead change (0 or more); got {}{}",
                                   key.text, num_text(v),
                                   key.is("INCR") ? " (use DECR for a shrinking lead)"
                                                  : " (use INCR for a growing lead)"));
    } else {
      pw.change_given = true;
      pw.lead_change = key.is("INCR") ? v : -v;
      pw.change_loc = key.loc;
    }
    a.no_more_numbers(key, fmt::format("one value ({},dv)", key.text));
  }
}

bool is_pitch_couplet_word(const Arg& a) {
  return is_pitch_unit(a) || a.is("MULTRD") || a.is("INCR") || a.is("DECR");
}

// Reports a repeated keyword; returns true when `p` is already set.
template <typename P>
bool twice(Args& a, const Arg& key, const P& p) {
  if (!p.set) return false;
  a.error(key.loc,
          fmt::format("{} is given twice (first at {})", key.text, a.where(p.loc, key.loc)));
  a.skip_numbers();
  return true;
}

// A word with one number in a range: DEPTH, STEP, OPTION, CUTANG, TLANGL.
struct RangedWord {
  std::string_view what;   // "the thread depth": "expected the thread depth after DEPTH, ..."
  std::string_view form;   // "one value (DEPTH,d)": "... DEPTH takes one value (DEPTH,d)"
  std::string_view range;  // "positive": "DEPTH must be positive; got -1"
  bool (*in_range)(double v);
};

bool is_positive(double v) {
  return std::isfinite(v) && v > 0;
}

template <typename T>
void parse_ranged(Args& a, const Arg& key, const RangedWord& word, ThreadParam<T>& p) {
  double v = 0;
  if (twice(a, key, p) || !a.number(key, word.what, v)) return;
  a.no_more_numbers(key, word.form);
  if (!word.in_range(v)) {
    a.error(key.loc, fmt::format("{} must be {}; got {}", key.text, word.range, num_text(v)));
    return;
  }
  if constexpr (std::is_same_v<T, int>) {
    p = {true, static_cast<int>(std::lround(v)), key.loc};
  } else {
    p = {true, v, key.loc};
  }
}

void parse_depth(Args& a, const Arg& key, ThreadWords& w) {
  parse_ranged(a, key, {"the thread depth", "one value (DEPTH,d)", "positive", is_positive},
               w.depth);
}

void parse_step(Args& a, const Arg& key, ThreadWords& w) {
  parse_ranged(a, key, {"the first infeed step", "one value (STEP,s)", "positive", is_positive},
               w.step);
}

void parse_option(Args& a, const Arg& key, ThreadWords& w) {
  parse_ranged(a, key,
               {"the infeed option (0 to 4)", "one value (OPTION,n)", "0, 1, 2, 3 or 4",
                [](double v) { return is_whole(v) && v >= 0 && v <= 4; }},
               w.option);
}

void parse_cutang(Args& a, const Arg& key, ThreadWords& w) {
  parse_ranged(
      a, key,
      {"the infeed angle in degrees", "one value (CUTANG,angle)", "between -360 and 360 degrees",
       [](double v) { return std::isfinite(v) && v >= -360 && v <= 360; }},
      w.cutang);
}

void parse_tlangl(Args& a, const Arg& key, ThreadWords& w) {
  parse_ranged(a, key,
               {"the tool nose angle in degrees", "one value (TLANGL,angle)",
                "more than 0 and less than 180 degrees",
                [](double v) { return std::isfinite(v) && v > 0 && v < 180; }},
               w.tlangl);
}

// Counts are positive whole numbers of at most kMaxPasses, steps positive: each bad one is
// reported.
bool check_cuts_numbers(Args& a, const std::vector<const Arg*>& nums) {
  bool ok = true;
  for (size_t k = 0; k < nums.size(); ++k) {
    const Arg& n = *nums[k];
    const bool is_count = k % 2 == 0;
    if (is_count) {
      if (!is_whole(n.number) || n.number < 1) {
        a.error(n.loc, fmt::format("CUTS count must be a positive whole number; got {}",
                                   num_text(n.number)));
        ok = false;
      } else if (n.number > kMaxPasses) {
        a.error(n.loc, fmt::format("CUTS count {} is more than the {} passes a thread may have",
                                   num_text(n.number), kMaxPasses));
        ok = false;
      }
    } else if (!std::isfinite(n.number) || n.number <= 0) {
      a.error(n.loc, fmt::format("CUTS step must be positive; got {}", num_text(n.number)));
      ok = false;
    }
  }
  return ok;
}

// CUTS at `key` with its checked numbers: a count alone, or count,step couplets.
CutsParam cuts_of(const Arg& key, const std::vector<const Arg*>& nums) {
  CutsParam c;
  c.set = true;
  c.loc = key.loc;
  if (nums.size() == 1) {
    c.count = static_cast<int>(std::lround(nums[0]->number));
    return c;
  }
  for (size_t k = 0; k + 1 < nums.size(); k += 2) {
    CutSteps s;
    s.count = static_cast<int>(std::lround(nums[k]->number));
    s.step = nums[k + 1]->number;
    s.loc = nums[k]->loc;
    c.count += s.count;
    c.steps.push_back(s);
  }
  return c;
}

// CUTS,c / CUTS,c,s / CUTS,n1,s1,n2,s2,...
void parse_cuts(Args& a, const Arg& key, ThreadWords& w) {
  if (twice(a, key, w.cuts)) return;
  std::vector<const Arg*> nums;
  while (a.peek_number()) nums.push_back(&a.take());
  if (nums.empty()) {
    a.error(key.loc, fmt::format("expected the number of passes after CUTS, found {}", a.found()));
    return;
  }
  if (nums.size() > 2 && nums.size() % 2 != 0) {
    a.error(key.loc, fmt::format("CUTS takes a count, a count and a step, or count,step pairs; "
                                 "got {} numbers (an odd count of more than 2)",
                                 nums.size()));
    return;
  }
  if (!check_cuts_numbers(a, nums)) return;
  w.cuts = cuts_of(key, nums);
}

// What a word with numbers is called in "expected <what> after KEY, found ..." and "KEY takes
// <form>".
struct WordForm {
  std::string_view what;
  std::string_view form;
};

// KEY,v[,second]: false (reported) when KEY is repeated or v is missing; a third number is
// reported and skipped.
template <typename P>
bool two_numbers(Args& a, const Arg& key, const P& p, WordForm word, double& v,
                 std::optional<double>& second) {
  if (twice(a, key, p) || !a.number(key, word.what, v)) return false;
  if (a.peek_number()) second = a.take().number;
  a.no_more_numbers(key, word.form);
  return true;
}

// FINCUT,count[,allowance].
void parse_fincut(Args& a, const Arg& key, ThreadWords& w) {
  double count = 0;
  std::optional<double> allowance;
  if (!two_numbers(a, key, w.fincut, {"the number of finish passes", "FINCUT,count[,allowance]"},
                   count, allowance))
    return;
  const double dist = allowance.value_or(0);
  if (!is_whole(count) || count < 0) {
    a.error(key.loc,
            fmt::format("FINCUT count must be a whole number, 0 or more; got {}", num_text(count)));
    return;
  }
  if (count > kMaxPasses) {
    a.error(key.loc, fmt::format("FINCUT count {} is more than the {} passes a thread may have",
                                 num_text(count), kMaxPasses));
    return;
  }
  if (!std::isfinite(dist) || dist < 0) {
    a.error(key.loc, fmt::format("FINCUT allowance must be 0 or more; got {}", num_text(dist)));
    return;
  }
  w.fincut.set = true;
  w.fincut.loc = key.loc;
  w.fincut.count = static_cast<int>(std::lround(count));
  w.fincut.dist = dist;
}

// ATANGL,angle[,height].
void parse_atangl(Args& a, const Arg& key, ThreadWords& w) {
  double v = 0;
  std::optional<double> height;
  if (!two_numbers(a, key, w.atangl, {"the pull-out angle in degrees", "ATANGL,angle[,height]"}, v,
                   height))
    return;
  const double h = height.value_or(0);
  if (!std::isfinite(v) || v < -80 || v > 80) {
    a.error(key.loc, fmt::format("ATANGL must be between -80 and 80 degrees; got {}", num_text(v)));
    return;
  }
  if (!std::isfinite(h) || h < 0) {
    a.error(key.loc, fmt::format("ATANGL height must be 0 or more (0: the default "
                                 "pitch/(2 tan 30)); got {}",
                                 num_text(h)));
    return;
  }
  w.atangl.set = true;
  w.atangl.loc = key.loc;
  w.atangl.angle = v;
  w.atangl.height = h;
}

// CHAMFR,length[,angle].
void parse_chamfr(Args& a, const Arg& key, ThreadWords& w) {
  double v = 0;
  std::optional<double> angle;
  if (!two_numbers(a, key, w.chamfr, {"the chamfer length", "CHAMFR,length[,angle]"}, v, angle))
    return;
  const bool angle_given = angle.has_value();
  const double beta = angle.value_or(45);
  if (!std::isfinite(v)) {
    a.error(key.loc, fmt::format("CHAMFR length must be a finite number; got {}", num_text(v)));
    return;
  }
  // CHAMFR,0 and CHAMFR,0,0 turn the chamfer off: the angle does not matter then.
  if (v != 0 && angle_given && (!std::isfinite(beta) || beta < 10 || beta > 80)) {
    a.error(key.loc,
            fmt::format("CHAMFR angle must be between 10 and 80 degrees; got {}", num_text(beta)));
    return;
  }
  w.chamfr.set = true;
  w.chamfr.loc = key.loc;
  w.chamfr.length = v;
  w.chamfr.angle_given = angle_given;
  w.chamfr.angle = angle_given ? beta : 45;
}

// RETURN[,height].
void parse_return(Args& a, const Arg& key, ThreadWords& w) {
  if (twice(a, key, w.ret)) return;
  w.ret.set = true;
  w.ret.loc = key.loc;
  if (!a.peek_number()) return;
  const double v = a.take().number;
  a.no_more_numbers(key, "RETURN[,height]");
  if (!std::isfinite(v) || v <= 0) {
    a.error(key.loc, fmt::format("RETURN height must be positive; got {}", num_text(v)));
    w.ret.set = false;
    return;
  }
  w.ret.height_given = true;
  w.ret.height = v;
}

// CHAIN: the GOTOs up to THREAD/OFF are the thread's contour (threading.md section 11).
void parse_chain(Args& a, const Arg& key, ThreadWords& w) {
  if (twice(a, key, w.chain)) return;
  w.chain = {true, true, key.loc};
  a.no_more_numbers(key, "no value");
}

// The THREAD/ON words other than the pitch couplets, and how each is parsed once its keyword has
// been taken.
struct ThreadWordRule {
  std::string_view word;
  void (*parse)(Args& a, const Arg& key, ThreadWords& w);
};
constexpr ThreadWordRule kThreadWordRules[] = {
    {"DEPTH", parse_depth},   {"CUTS", parse_cuts},     {"STEP", parse_step},
    {"FINCUT", parse_fincut}, {"OPTION", parse_option}, {"CUTANG", parse_cutang},
    {"TLANGL", parse_tlangl}, {"ATANGL", parse_atangl}, {"CHAMFR", parse_chamfr},
    {"RETURN", parse_return}, {"CHAIN", parse_chain},
};

const ThreadWordRule* find_thread_word(const Arg& key) {
  for (const ThreadWordRule& rule : kThreadWordRules) {
    if (key.is(rule.word)) return &rule;
  }
  return nullptr;
}

// The pitch words of one statement as they are read.
struct PitchReading {
  PitchWords pw;
  std::string pitch_word;    // what gave the pitch value, for "already given by ..."
  bool qualifiable = false;  // a leading value not yet qualified by TPI|IPR|MMPR|PERREV
  double leading = 0;
};

// PITCH/v: the leading value, threads per CL unit unless a unit word follows.
void leading_value(Args& a, LengthUnit cl_units, PitchReading& s) {
  const Arg& n = a.take();
  if (s.pw.value_given) {
    a.error(n.loc, fmt::format("unexpected number {}: the pitch is already given by {} at {}",
                               n.text, s.pitch_word, a.where(s.pw.value_loc, n.loc)));
    a.skip_numbers();
    return;
  }
  if (!std::isfinite(n.number) || n.number <= 0) {
    a.error(n.loc, fmt::format("the pitch value must be positive; got {}", num_text(n.number)));
    a.skip_numbers();
    return;
  }
  s.leading = n.number;
  set_pitch("", s.leading, cl_units, n.loc, s.pw);
  s.pitch_word = fmt::format("the value {}", n.text);
  s.qualifiable = true;
}

// PITCH/v,TPI: the unit word `key` (with no number after it) qualifies the leading value.
void qualify_leading(Args& a, const Arg& key, LengthUnit cl_units, PitchReading& s) {
  if (!s.qualifiable) {
    a.error(key.loc, fmt::format("expected {} after {}, found {}", unit_what(key.text), key.text,
                                 a.found()));
    return;
  }
  const SourceLoc vloc = s.pw.value_loc;
  set_pitch(key.text, s.leading, cl_units, vloc, s.pw);
  s.pitch_word = fmt::format("{} {}", num_text(s.leading), key.text);
  s.qualifiable = false;
}

}  // namespace

bool parse_thread_words(const Statement& st, size_t first_arg, LengthUnit cl_units,
                        ThreadWords& out, Diagnostics& diags) {
  Args a(st, first_arg, diags);
  ThreadWords w;
  std::string pitch_word;
  while (!a.done()) {
    if (a.peek_number()) {
      const Arg& n = a.take();
      a.error(n.loc, fmt::format("expected a thread parameter word, found number {}; valid "
                                 "words: {}",
                                 n.text, kThreadWordList));
      a.skip_numbers();
      continue;
    }
    const Arg& key = a.take();
    if (const ThreadWordRule* rule = find_thread_word(key)) {
      rule->parse(a, key, w);
    } else if (is_pitch_couplet_word(key)) {
      pitch_couplet(a, key, cl_units, w.pitch, pitch_word);
    } else {
      a.error(key.loc, key.is_word() ? fmt::format("unknown thread parameter '{}'; valid words: {}",
                                                   key.text, kThreadWordList)
                                     : fmt::format("expected a thread parameter word, found {}; "
                                                   "valid words: {}",
                                                   a.shown(key), kThreadWordList));
      a.skip_numbers();
    }
  }
  if (!a.ok()) return false;
  out = std::move(w);
  return true;
}

bool parse_pitch_words(const Statement& st, size_t first_arg, LengthUnit cl_units, PitchSpec& pitch,
                       Diagnostics& diags) {
  Args a(st, first_arg, diags);
  PitchReading s;
  while (!a.done()) {
    if (a.peek_number()) {
      leading_value(a, cl_units, s);
      continue;
    }
    const Arg& key = a.take();
    if (is_pitch_unit(key) && !a.peek_number()) {
      qualify_leading(a, key, cl_units, s);
      continue;
    }
    s.qualifiable = false;
    if (is_pitch_couplet_word(key)) {
      pitch_couplet(a, key, cl_units, s.pw, s.pitch_word);
    } else {
      a.error(key.loc, key.is_word()
                           ? fmt::format("unknown pitch word '{}'; valid words: {}", key.text,
                                         kPitchWordList)
                           : fmt::format("expected a pitch word, found {}; valid words: {}",
                                         a.shown(key), kPitchWordList));
      a.skip_numbers();
    }
  }
  if (!a.ok()) return false;
  if (st.major == "PITCH" && !s.pw.value_given) {
    diags.error(st.loc, st.line_text(st.loc.line),
                "PITCH needs a value: PITCH/v[,TPI|IPR|MMPR|PERREV][,MULTRD,n][,INCR|DECR,dv]");
    return false;
  }
  s.pw.apply_to(pitch);
  return true;
}

}  // namespace clpost
