// codegen/InlineSingleUse: single-use temporaries folded into their reader. The witness is an
// evaluator of the emitted C++ subset written here from the language's rules (precedence, left
// associativity, unary minus), independent of the inliner's own parenthesisation rules: random
// straight-line programs must give bitwise the same results before and after (the same operations
// in the same order), and fewer statements.
#include <gtest/gtest.h>

#include <cctype>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "StatementEvaluator.h"
#include "codegen/InlineSingleUse.h"

namespace
{
using rbdgen::cg::inlineSingleUse;

using rbdgen::test::run;

TEST(InlineSingleUse, KeepsOperationOrderAndSignsExactly)
{
  const std::vector<std::string> lines = {
      "const S a = x * y;",          // single use, first factor: a * z is x * y * z
      "const S b = a * z;",          //
      "const S c = x + y;",          // single use after '*': parenthesised
      "const S d = z * c;",          //
      "const S e = -x * y;",         // single use after binary '-': the sign moves to the operator
      "const S f = z - e;",          //
      "const S g = x - y;",          // single use after '-': parenthesised
      "const S h = z - g;",          //
      "const S u = y * z;",          // read twice: kept
      "out[0] = b + d + f + h + u;", //
      "out[1] = -u;",                //
  };
  const std::vector<std::string> expected = {
      "const S u = y * z;",
      "out[0] = x * y * z + z * (x + y) + (z + x * y) + (z - (x - y)) + u;",
      "out[1] = -u;",
  };
  EXPECT_EQ(inlineSingleUse(lines), expected);
}

TEST(InlineSingleUse, DoesNotMoveReadsAcrossWritesOrIntoLoops)
{
  const std::vector<std::string> lines = {
      "const S a = m(0, 0) * x;", // reads m: cannot move past m(0, 0) = ...
      "m(0, 0) = y;",             //
      "out[0] = a;",              //
      "const S b = x * y;",       // into a loop header: never
      "for(int i = 0; i < b; ++i)",
      "const S c = x - y;",       // across a write of another object: moves
      "out[1] = y;",              //
      "out[2] = c;",              //
  };
  const std::vector<std::string> out = inlineSingleUse(lines);
  EXPECT_EQ(out[0], "const S a = m(0, 0) * x;");
  EXPECT_EQ(out[3], "const S b = x * y;");
  EXPECT_EQ(out.back(), "out[2] = x - y;");
}

// Named model constants (`S(model::j1.rx)`) fold like literals; a call of a qualified function
// (`std::sin(x)`, `detail::Lanes<S>::sqrt(x)`) stays where it is; a name after `::` or `.` is not a local.
TEST(InlineSingleUse, FoldsNamedConstantsButNotQualifiedCalls)
{
  const std::vector<std::string> lines = {
      "const S a = S(model::j1.rx) * x;",
      "out[0] = a + y;",
      "const S b = std::sin(x);",
      "out[1] = b;",
      "const S c = detail::Lanes<S>::sqrt(x);",
      "out[2] = c;",
      "const S j1 = x * y;",        // a local named like the model constant's member path
      "out[3] = S(model::j1.m) * j1;", // only the second j1 is a read of the local
  };
  const std::vector<std::string> out = inlineSingleUse(lines);
  ASSERT_EQ(out.size(), 6u);
  EXPECT_EQ(out[0], "out[0] = S(model::j1.rx) * x + y;");
  EXPECT_EQ(out[1], "const S b = std::sin(x);");
  EXPECT_EQ(out[3], "const S c = detail::Lanes<S>::sqrt(x);");
  EXPECT_EQ(out[5], "out[3] = S(model::j1.m) * (x * y);");
}

TEST(InlineSingleUse, RespectsTheLineLength)
{
  const std::vector<std::string> lines = {"const S a = xxxxxxxxxx * yyyyyyyyyy;", "out[0] = zzzzzzzzzz * a;"};
  EXPECT_EQ(inlineSingleUse(lines, 30), lines);
  EXPECT_EQ(inlineSingleUse(lines, 60), std::vector<std::string>{"out[0] = zzzzzzzzzz * (xxxxxxxxxx * yyyyyyyyyy);"});
}

// Random programs in the form Block emits (sums of signed products, constants last), each
// temporary read once or more: same bits before and after, fewer lines.
TEST(InlineSingleUse, RandomProgramsGiveBitwiseTheSameResults)
{
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  int removedTotal = 0;
  for(int trial = 0; trial < 300; ++trial)
  {
    std::map<std::string, double> inputs;
    std::vector<std::string> names;
    for(const char * n : {"x", "y", "z", "w"})
    {
      inputs[n] = value(rng);
      names.push_back(n);
    }
    inputs["m(0, 1)"] = value(rng);
    names.push_back("m(0, 1)");
    std::vector<std::string> lines;
    const int count = 4 + static_cast<int>(rng() % 12);
    for(int k = 0; k < count; ++k)
    {
      std::string rhs;
      const int terms = 1 + static_cast<int>(rng() % 3);
      for(int t = 0; t < terms; ++t)
      {
        const bool negative = rng() % 2 == 0;
        std::string term;
        if(rng() % 3 == 0) term = "S(" + std::to_string(0.5 + static_cast<int>(rng() % 7)) + ") * ";
        term += names[rng() % names.size()];
        if(rng() % 2 == 0) term += (rng() % 4 == 0 ? " / " : " * ") + names[rng() % names.size()];
        rhs += t == 0 ? (negative ? "-" : "") + term : (negative ? " - " : " + ") + term;
      }
      if(rng() % 4 == 0) rhs += " + S(0.25)";
      const std::string name = "t" + std::to_string(k);
      lines.push_back("const S " + name + " = " + rhs + ";");
      names.push_back(name);
      if(rng() % 4 == 0) lines.push_back("out[" + std::to_string(k) + "] " + (rng() % 2 ? "-= " : "= ") + name + ";");
    }
    lines.push_back("out[99] = " + names.back() + ";");
    const std::vector<std::string> inlined = inlineSingleUse(lines, 400);
    const std::vector<double> before = run(lines, inputs), after = run(inlined, inputs);
    ASSERT_EQ(before.size(), after.size());
    for(std::size_t i = 0; i < before.size(); ++i)
      ASSERT_EQ(std::memcmp(&before[i], &after[i], sizeof(double)), 0)
          << "trial " << trial << " output " << i << ": " << before[i] << " vs " << after[i];
    removedTotal += static_cast<int>(lines.size() - inlined.size());
  }
  EXPECT_GT(removedTotal, 300); // it does fold (about one temporary in three is read once)
}

} // namespace
