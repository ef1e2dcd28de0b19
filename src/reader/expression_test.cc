#include "reader/expression.h"

#include <gtest/gtest.h>

#include <string>

namespace clpost::reader {
namespace {

// The value of the expression at the start of `src`, and where it stopped: "value @end", or
// "error @at: message".
std::string eval(std::string_view src) {
  size_t pos = 0;
  double v = 0;
  ExprError e;
  char buf[64];
  if (!eval_expression(src, pos, v, e)) return "error @" + std::to_string(e.at) + ": " + e.message;
  std::snprintf(buf, sizeof buf, "%.17g @%zu", v, pos);
  return buf;
}

TEST(Expression, Values) {
  EXPECT_EQ(eval("(1/2.5)"), "0.40000000000000002 @7");
  EXPECT_EQ(eval("(2*3+1),X"), "7 @7");
  EXPECT_EQ(eval("(2+3*4-6/2)"), "11 @11");
  EXPECT_EQ(eval("((2+3)*4)"), "20 @9");
  EXPECT_EQ(eval("-(1+2) ,"), "-3 @6");  // the blank after it is not the expression's
  EXPECT_EQ(eval("+ ( 4 )"), "4 @7");
  EXPECT_EQ(eval("(-2**2)"), "-4 @7");     // power above unary minus
  EXPECT_EQ(eval("(2**3**2)"), "512 @9");  // right-associative
  EXPECT_EQ(eval("(2**-1)"), "0.5 @7");
  EXPECT_EQ(eval("(--3)"), "3 @5");
  EXPECT_EQ(eval("(1.5E2/.5e1)"), "30 @12");
  EXPECT_EQ(eval("(1)**2"), "1 @6");
}

TEST(Expression, Errors) {
  EXPECT_EQ(eval("(1/0)"), "error @2: division by zero");
  EXPECT_EQ(eval("(1/(1-1))"), "error @2: division by zero");
  EXPECT_EQ(eval("(1"), "error @0: missing ')' to close this '('");
  EXPECT_EQ(eval("(1+(2)"), "error @0: missing ')' to close this '('");
  EXPECT_EQ(eval("(1+)"), "error @3: expected a number in the expression, found ')'");
  EXPECT_EQ(eval("(A)"), "error @1: expected a number in the expression, found 'A'");
  EXPECT_EQ(eval("(1 2)"), "error @3: expected an operator or ')' in the expression, found '2'");
  EXPECT_EQ(eval("(1.2.3)"), "error @1: invalid number '1.2.3'");
  EXPECT_EQ(eval("(1e999)"), "error @1: number '1e999' is out of range");
  EXPECT_EQ(eval("(1e300*1e300)"), "error @6: the result is out of range");
  EXPECT_EQ(eval("((-1)**0.5)"), "error @5: the result is not a number");
  EXPECT_EQ(eval("(0**-1)"), "error @2: the result is out of range");
  EXPECT_EQ(eval("(1+"), "error @3: expected a number, found the end of the statement");
}

TEST(Expression, NestingIsBounded) {
  const std::string deep =
      std::string(kMaxNesting + 1, '(') + "1" + std::string(kMaxNesting + 1, ')');
  EXPECT_EQ(eval(deep),
            "error @" + std::to_string(kMaxNesting) + ": parentheses nested too deeply");
  const std::string ok = std::string(kMaxNesting, '(') + "1" + std::string(kMaxNesting, ')');
  EXPECT_EQ(eval(ok), "1 @" + std::to_string(ok.size()));
  EXPECT_EQ(eval("(" + std::string(100000, '-') + "1)"), "error @64: expression nested too deeply");
}

}  // namespace
}  // namespace clpost::reader
