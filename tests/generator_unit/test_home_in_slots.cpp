// codegen/HomeInSlots: values copied into array slots computed into their slot. Witnesses: the
// statement evaluator (StatementEvaluator.h) on random straight-line programs (every output, every
// slot and every name bitwise the same before and after, fewer lines), and the rules written out on
// a small program (which copy becomes the home, which slots are left alone, declarations moved up).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "StatementEvaluator.h"
#include "codegen/HomeInSlots.h"

namespace
{
using rbdgen::cg::homeInSlots;
using rbdgen::test::run;

TEST(HomeInSlots, TheFirstCopyBecomesTheHome)
{
  const std::vector<std::string> lines = {
      "const S a = x * y;",
      "const S b = a + z;",     // reads a: reads its slot after
      "const S c = x - y;",     // copied into a slot written twice: left alone
      "const S e = y * y;",     // copied into an array not named: left alone
      "S arr[2][3];",           // declared after the definitions: moves up
      "Eigen::Matrix<S, 4, 2> pair_ub;",
      "arr[0][1] = a;",         // home of a
      "pair_ub(3, 1) = a;",     // a second copy: copies the home
      "arr[1][2] = b;",         // home of b
      "arr[1][0] = c;",
      "arr[1][0] = x;",
      "other[0][0] = e;",
      "[&]() {",
      "  out[1] = a + b;",      // inside a lambda: reads the slots
      "  arr[0][0] = c;",       // not top level: not a home
      "}();",
      "out[0] = a * b;",
  };
  const std::vector<std::string> expected = {
      "S arr[2][3];",
      "arr[0][1] = x * y;",
      "arr[1][2] = arr[0][1] + z;",
      "const S c = x - y;",
      "const S e = y * y;",
      "Eigen::Matrix<S, 4, 2> pair_ub;",
      "pair_ub(3, 1) = arr[0][1];",
      "arr[1][0] = c;",
      "arr[1][0] = x;",
      "other[0][0] = e;",
      "[&]() {",
      "  out[1] = arr[0][1] + arr[1][2];",
      "  arr[0][0] = c;",
      "}();",
      "out[0] = arr[0][1] * arr[1][2];",
  };
  EXPECT_EQ(homeInSlots(lines, {"arr", "pair_ub"}), expected);
}

// An array read slot by slot only: a further copy of a homed value into it goes, and its slot's
// reads read the home; a copy of a value with no home stays.
TEST(HomeInSlots, CopiesIntoAnArrayReadByElementGo)
{
  const std::vector<std::string> lines = {
      "const S a = x * y;",
      "const S b = x + y;",
      "S in[1][2];",
      "S pj[2][2];",
      "in[0][1] = a;",     // home of a
      "pj[1][0] = a;",     // an alias of in[0][1]
      "pj[1][1] = x;",     // x has no home: stays
      "out[0] = pj[1][0] * pj[1][1] + pj[1][0];",
      "pj[0][0] = b;",     // the first copy of b: its home
      "out[1] = pj[0][0];",
  };
  const std::vector<std::string> expected = {
      "S in[1][2];",
      "in[0][1] = x * y;",
      "S pj[2][2];",
      "pj[0][0] = x + y;",
      "pj[1][1] = x;",
      "out[0] = in[0][1] * pj[1][1] + in[0][1];",
      "out[1] = pj[0][0];",
  };
  EXPECT_EQ(homeInSlots(lines, {"in", "pj"}, {"pj"}), expected);
}

// A line declaring several arrays moves up (once) to the first home in any of them.
TEST(HomeInSlots, ALineDeclaringSeveralArraysMovesOnce)
{
  const std::vector<std::string> lines = {
      "const S a = x * y;",
      "const S b = x + y;",
      "S pu[2][2], pb[2][2], ps[2][2];",
      "pb[0][0] = b;",
      "ps[1][1] = a;",
      "out[0] = pb[0][0] + ps[1][1];",
  };
  const std::vector<std::string> expected = {
      "S pu[2][2], pb[2][2], ps[2][2];",
      "ps[1][1] = x * y;",
      "pb[0][0] = x + y;",
      "out[0] = pb[0][0] + ps[1][1];",
  };
  EXPECT_EQ(homeInSlots(lines, {"pu", "pb", "ps"}), expected);
}

// An array changed in place after the copies (the LTDL factors): a value still read after the first
// line that changes the array keeps its name (its slot no longer holds it there); the others are
// homed as usual.
TEST(HomeInSlots, ValuesReadAfterAnInPlaceChangeKeepTheirNames)
{
  const std::vector<std::string> lines = {
      "const S a = x * y;",
      "const S b = x + y;",
      "S lt[3];",
      "RBDGEN_IN_MEMORY(lt);", // names the array before the copies: no change after them
      "lt[0] = a;",
      "lt[1] = b;",
      "lt[2] = x;",
      "out[0] = b;",           // before the change: reads b's home
      "{ const S s = lt[0] * z; scale(lt, s); }",
      "out[1] = a + lt[1];",   // a read after the change: a keeps its name
  };
  const std::vector<std::string> expected = {
      "const S a = x * y;",
      "S lt[3];",
      "lt[1] = x + y;",
      "RBDGEN_IN_MEMORY(lt);",
      "lt[0] = a;",
      "lt[2] = x;",
      "out[0] = lt[1];",
      "{ const S s = lt[0] * z; scale(lt, s); }",
      "out[1] = a + lt[1];",
  };
  EXPECT_EQ(homeInSlots(lines, {"lt"}, {}, {"lt"}), expected);
  // (without the rule a would be homed too, and out[1] would read the changed slot lt[0])
  EXPECT_EQ(homeInSlots(lines, {"lt"})[1], "lt[0] = x * y;");
  // a compound assignment to a slot changes the array too
  std::vector<std::string> compound = lines;
  compound[8] = "lt[0] *= z;";
  std::vector<std::string> expectedCompound = expected;
  expectedCompound[7] = "lt[0] *= z;";
  EXPECT_EQ(homeInSlots(compound, {"lt"}, {}, {"lt"}), expectedCompound);
}

TEST(HomeInSlots, NamesAfterADotOrInLongerNamesAreNotReads)
{
  const std::vector<std::string> lines = {
      "const S a = x * y;",
      "S arr[1][1];",
      "arr[0][0] = a;",
      "out[0] = X0s.a + a_b + a;",
  };
  const std::vector<std::string> expected = {
      "S arr[1][1];",
      "arr[0][0] = x * y;",
      "out[0] = X0s.a + a_b + arr[0][0];",
  };
  EXPECT_EQ(homeInSlots(lines, {"arr"}), expected);
}

// Random programs in the form the derivatives emit: temporaries, copies of some into slots of two
// arrays (some slots written twice, some names copied twice), outputs reading names and written
// slots. Every value is bitwise the same before and after, and the copies go.
TEST(HomeInSlots, RandomProgramsKeepEveryValue)
{
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  int removedTotal = 0;
  for(int trial = 0; trial < 300; ++trial)
  {
    std::map<std::string, double> inputs;
    std::vector<std::string> names, readable;
    for(const char * n : {"x", "y", "z"})
    {
      inputs[n] = value(rng);
      names.push_back(n);
    }
    readable = names;
    std::vector<std::string> lines = {"S arr[3][3];"};
    std::set<std::string> written;
    const int count = 4 + static_cast<int>(rng() % 14);
    for(int k = 0; k < count; ++k)
    {
      std::string rhs;
      const int terms = 1 + static_cast<int>(rng() % 3);
      for(int t = 0; t < terms; ++t)
      {
        std::string term = readable[rng() % readable.size()];
        if(rng() % 2 == 0) term += " * " + readable[rng() % readable.size()];
        rhs += t == 0 ? (rng() % 2 ? "-" : "") + term : (rng() % 2 ? " - " : " + ") + term;
      }
      const std::string name = "t" + std::to_string(k);
      lines.push_back("const S " + name + " = " + rhs + ";");
      names.push_back(name);
      readable.push_back(name);
      const int copies = static_cast<int>(rng() % 3);
      for(int c = 0; c < copies; ++c)
      {
        const bool matrix = rng() % 3 == 0;
        const std::string slot = matrix ? "pm(" + std::to_string(rng() % 3) + ", " + std::to_string(rng() % 2) + ")"
                                        : "arr[" + std::to_string(rng() % 3) + "][" + std::to_string(rng() % 3) + "]";
        // a copy of an earlier name now and then (the slot then holds another value)
        const std::string from = rng() % 4 == 0 ? names[3 + rng() % (names.size() - 3)] : name;
        lines.push_back(slot + " = " + from + ";");
        if(written.insert(slot).second) readable.push_back(slot);
      }
      if(rng() % 3 == 0) lines.push_back("out[" + std::to_string(k) + "] = " + readable[rng() % readable.size()] + ";");
    }
    // pm declared after some definitions (before its first use): its declaration may move up
    std::size_t at = 1 + rng() % 4;
    for(std::size_t k = 0; k < lines.size(); ++k)
      if(lines[k].rfind("pm(", 0) == 0) at = std::min(at, k);
    lines.insert(lines.begin() + static_cast<long>(std::min(at, lines.size())), "Eigen::Matrix<S, 3, 2> pm;");
    // a slot read before it is written would read nothing: the programs read written slots only,
    // so a slot written again later is read with its first or its second value depending on order
    const std::vector<std::string> homed =
        trial % 2 ? homeInSlots(lines, {"arr", "pm"}) : homeInSlots(lines, {"arr", "pm"}, {"arr"});
    std::map<std::string, double> before, after;
    const std::vector<double> outBefore = run(lines, inputs, &before), outAfter = run(homed, inputs, &after);
    ASSERT_EQ(outBefore.size(), outAfter.size());
    for(std::size_t i = 0; i < outBefore.size(); ++i)
      ASSERT_EQ(std::memcmp(&outBefore[i], &outAfter[i], sizeof(double)), 0) << "trial " << trial << " output " << i;
    for(const auto & [name, v] : before)
    {
      // a homed temporary is no longer a name: its slot holds its value
      if(!after.count(name)) continue;
      ASSERT_EQ(std::memcmp(&v, &after.at(name), sizeof(double)), 0) << "trial " << trial << " " << name;
    }
    // every slot keeps its value, or (an alias, trials read by element) is no longer written
    for(const std::string & slot : written)
      ASSERT_TRUE(after.count(slot) || (trial % 2 == 0 && slot.rfind("arr", 0) == 0)) << "trial " << trial << " " << slot;
    // every array is declared before its first use
    for(const std::string & array : {std::string("arr"), std::string("pm")})
    {
      std::size_t decl = homed.size(), use = homed.size();
      for(std::size_t k = 0; k < homed.size(); ++k)
      {
        const bool declares = homed[k].rfind("S " + array + "[", 0) == 0 || homed[k] == "Eigen::Matrix<S, 3, 2> " + array + ";";
        if(declares) decl = std::min(decl, k);
        else if(homed[k].find(array + (array == "pm" ? "(" : "[")) != std::string::npos) use = std::min(use, k);
      }
      ASSERT_LT(decl, use) << "trial " << trial << " " << array;
    }
    removedTotal += static_cast<int>(lines.size() - homed.size());
  }
  EXPECT_GT(removedTotal, 300); // copies do go (about one per temporary)
}

} // namespace
