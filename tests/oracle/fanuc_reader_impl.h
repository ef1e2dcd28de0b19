#pragma once
// The Fanuc/Haas/NCT reader's state and its block handlers (fanuc_reader.cc: words, modes,
// motion; fanuc_cycles.cc: the threading cycles; nct_thread.cc: NCT's G33). Internal to the
// oracle; fanuc_reader.h is the interface.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "fanuc_cycles.h"
#include "fanuc_reader.h"

namespace oracle::fanuc_detail {

struct Word {
  char letter = 0;
  double value = 0;
  bool point = false;  // written with a decimal point
};

struct Block {
  std::vector<Word> words;
  bool optional = false;  // "/" first
  const Word* find(char letter) const {
    for (const Word& w : words)
      if (w.letter == letter) return &w;
    return nullptr;
  }
  bool has_g(int code) const {
    for (const Word& w : words)
      if (w.letter == 'G' && w.value == code) return true;
    return false;
  }
};

class Control {
 public:
  explicit Control(Dialect d) : d_(d) {}
  // False when the control stops here (error_).
  bool block(const Block& b, int line, std::string_view text);
  bool ended() const { return ended_; }
  ControlRun run;

 private:
  bool fail(const std::string& why) {
    run.error = why;
    return false;
  }
  double unit() const { return *inch_ ? kMmPerInch : 1; }
  bool code(int g);
  int clamp_code() const { return d_ == Dialect::kNct ? 92 : 50; }
  bool length(const Block& b, char letter, std::optional<double>& mm);
  bool modes(const Block& b);
  bool spindle_and_tool(const Block& b);
  bool mcode(int m);
  bool dwell(const Block& b);
  bool home(const Block& b);
  // fanuc_cycles.cc: G92, G76
  bool g92(const Block& b);
  bool g76(const Block& b);
  bool g76_first(const Block& b);
  bool haas_g76(const Block& b);
  bool cycle_end(const Block& b, std::optional<double>& x, std::optional<double>& z);
  void g76_passes(const std::vector<double>& depths, CyclePoint end, double k, double taper,
                  double angle, double lead);
  // nct_thread.cc: G33's lead (F or E) and start angle (Q), and its F outside G33
  bool nct_lead(const Block& b, Event& e);
  bool nct_feed(const Word& f);
  double increment() const { return *inch_ ? 0.0001 * kMmPerInch : 0.001; }
  bool motion(const Block& b);
  bool arc(const Block& b, Event& e);
  void push(Event e);
  Modal modal() const;

  Dialect d_;
  std::optional<bool> inch_;   // [0i-T] "Inch/metric conversion": power-on unit is a parameter
  std::optional<int> motion_;  // group 01; its power-on code is parameter 3402#0
  std::optional<bool> per_rev_;
  std::optional<double> x_, z_;  // mm, X a radius; unknown after a reference return
  double f_ = 0;
  bool f_given_ = false;
  double s_ = 0, clamp_ = 0;
  bool css_ = false, s_css_ = false, on_ = false, ccw_ = false;
  int tool_ = 0, offset_ = 0;
  Coolant coolant_;
  // [0i-T] "Single repetitive cycle": "data items X (U), Z (W), and R in a canned cycle are
  // modal"; G76's first block's m, r, a, Δdmin, d are modal [ctl] (their power-on values are
  // parameters 5142, 5130, 5143, 5140, 5141: the reader needs the first block).
  std::optional<double> cycle_x_, cycle_z_;
  double cycle_r_ = 0;
  struct G76First {
    int m = 0, chamfer = 0, angle = 0;
    double min_cut = 0, allowance = 0;
  };
  std::optional<G76First> g76_;
  // NCT G33 [seed 002]: the lead of the last F given in a G33 block (mm/rev); whether the F in
  // force was given there (its meaning as a feed is not documented); whether the block before
  // was a G33 move (the next one continues its thread without synchronising).
  double lead_ = 0;
  bool f_is_lead_ = false, thread_chain_ = false;
  bool home_x_ = false, home_z_ = false;  // the axes the return the block before is part of
  bool ended_ = false;
  int line_ = 0;
  std::string text_;
};

}  // namespace oracle::fanuc_detail
