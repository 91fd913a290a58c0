// `rbdgen simulate`, run as a user runs it: CSV (header, one row per step, energies adding up),
// the gnuplot script and a PNG, the warning path without gnuplot, one-line errors and no output.
#include <fstream>
#include <sstream>

#include "CliRun.h"

using namespace clitest;

namespace
{

std::string scene(const std::string & name) { return std::string(RBDGEN_SOURCE_DIR) + "/scenes/" + name + ".xml"; }

std::vector<std::vector<std::string>> readCsv(const fs::path & p)
{
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(p);
  for(std::string line; std::getline(in, line);)
  {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for(std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

using SimulateCli = CliTest;

} // namespace

TEST_F(SimulateCli, WritesCsvScriptAndPng)
{
  const Result r = rbdgen({"simulate", scene("pendulum_damped"), "--duration", "0.5", "--out", "traj.csv"}, dir());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = readCsv(dir() / "traj.csv");
  ASSERT_EQ(rows.size(), 502u); // header + t = 0 + 500 steps of 1 ms
  const std::vector<std::string> header = {"t", "q_joint1", "alpha_joint1", "kinetic", "potential", "contact_energy",
                                           "total_energy"};
  EXPECT_EQ(rows[0], header);
  EXPECT_EQ(std::stod(rows[1][1]), 1.0); // <initial joint="joint1" q="1.0"/>
  EXPECT_NEAR(std::stod(rows.back()[0]), 0.5, 1e-12);
  for(std::size_t k = 1; k < rows.size(); ++k)
  {
    ASSERT_EQ(rows[k].size(), header.size());
    EXPECT_NEAR(std::stod(rows[k][6]), std::stod(rows[k][3]) + std::stod(rows[k][4]) + std::stod(rows[k][5]), 1e-8);
    // pendulum: V = -m g l cos(q) with m = 1, l = 1
    EXPECT_NEAR(std::stod(rows[k][4]), -9.81 * std::cos(std::stod(rows[k][1])), 1e-8);
  }
  EXPECT_TRUE(fs::exists(dir() / "traj.gp"));
  const std::string png = readFile(dir() / "traj.png");
  ASSERT_GT(png.size(), 1000u) << r.err;
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_NE(r.out.find("traj.png"), std::string::npos);
  EXPECT_EQ(listTree(dir()), (std::vector<std::string>{"traj.csv", "traj.gp", "traj.png"}));
}

TEST_F(SimulateCli, ContactForcesAndPlotPath)
{
  const Result r = rbdgen({"simulate", scene("quadruped_standing"), "--duration", "0.05", "--integrator", "rk4", "--out",
                           "q.csv", "--plot", "plot.png"},
                          dir());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = readCsv(dir() / "q.csv");
  ASSERT_GE(rows.size(), 2u);
  EXPECT_EQ(rows[0].back(), "fn_HR_foot");
  EXPECT_EQ(rows[0][1], "q_Root_0");
  EXPECT_TRUE(fs::exists(dir() / "plot.png"));
}

TEST_F(SimulateCli, WithoutGnuplotWritesCsvAndScriptAndWarns)
{
  const Result r = runShell("PATH=/nonexistent " + shellQuote(RBDGEN_EXE) + " simulate " + shellQuote(scene("pendulum_damped")) +
                                " --duration 0.01 --out t.csv",
                            dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("rbdgen: warning: gnuplot not found"), std::string::npos) << r.err;
  EXPECT_EQ(listTree(dir()), (std::vector<std::string>{"t.csv", "t.gp"}));
}

TEST_F(SimulateCli, ErrorsAreOneLineAndWriteNothing)
{
  writeFile(dir() / "bad.xml", "<scene name=\"b\">\n  <robot urdf=\"" + robot("pendulum").string() +
                                   "\"/>\n  <simulation dt=\"-1\"/>\n</scene>\n");
  Result r = rbdgen({"simulate", "bad.xml", "--out", "x.csv"}, dir());
  EXPECT_TRUE(isOneLineError(r));
  EXPECT_NE(r.err.find("rbdgen: error: bad.xml:3: simulation: dt = -1 must be > 0"), std::string::npos) << r.err;
  r = rbdgen({"simulate", scene("pendulum_damped"), "--dt", "0", "--out", "x.csv"}, dir());
  EXPECT_TRUE(isOneLineError(r));
  r = rbdgen({"simulate", scene("pendulum_damped"), "--integrator", "leapfrog", "--out", "x.csv"}, dir());
  EXPECT_TRUE(isOneLineError(r));
  r = rbdgen({"simulate", "missing.xml"}, dir());
  EXPECT_TRUE(isOneLineError(r));
  // a diverging run (10 ms explicit Euler on stiff contacts) leaves no partial CSV
  r = rbdgen({"simulate", scene("quadruped_standing"), "--dt", "0.01", "--integrator", "explicit_euler", "--out", "x.csv"}, dir());
  EXPECT_TRUE(isOneLineError(r));
  EXPECT_NE(r.err.find("simulation diverged at t = "), std::string::npos) << r.err;
  EXPECT_EQ(listTree(dir()), std::vector<std::string>{"bad.xml"});
}
