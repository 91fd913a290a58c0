// `rbdgen accuracy` run as a user runs it, on the double pendulum (a few seconds: the driver is
// compiled). Every variant's error must be finite and within its stated bound; double must be
// more accurate than float; the files and plots must be there. Errors: one line, non-zero exit,
// nothing written.
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "CliRun.h"

namespace
{

using clitest::CliTest;
namespace fs = std::filesystem;

/// accuracy.csv as rows of column name -> text.
std::vector<std::map<std::string, std::string>> readCsv(const std::string & text)
{
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  const auto split = [](const std::string & l) {
    std::vector<std::string> f;
    std::string cur;
    for(char c : l)
    {
      if(c == ',')
      {
        f.push_back(cur);
        cur.clear();
      }
      else
        cur += c;
    }
    f.push_back(cur);
    return f;
  };
  std::getline(in, line);
  header = split(line);
  while(std::getline(in, line))
  {
    const auto f = split(line);
    std::map<std::string, std::string> row;
    for(std::size_t i = 0; i < header.size() && i < f.size(); ++i) row[header[i]] = f[i];
    rows.push_back(row);
  }
  return rows;
}

class AccuracyStudy : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    tmp_ = new clitest::TempDir;
    result_ = clitest::rbdgen({"accuracy", (fs::path(RBDGEN_SOURCE_DIR) / "robots" / "double_pendulum.urdf").string(), "--out",
                               "out", "--states", "200", "--horizon", "0.2"},
                              tmp_->path());
    out_ = tmp_->path() / "out";
  }
  static void TearDownTestSuite() { delete tmp_; }
  static clitest::TempDir * tmp_;
  static clitest::Result result_;
  static fs::path out_;
};
clitest::TempDir * AccuracyStudy::tmp_ = nullptr;
clitest::Result AccuracyStudy::result_;
fs::path AccuracyStudy::out_;

} // namespace

/// Every file and plot is written, and its path printed.
static void checkFiles(const clitest::Result & result_, const fs::path & out_)
{
  ASSERT_EQ(result_.code, 0) << result_.err;
  for(const char * f : {"accuracy.md", "accuracy.csv", "accuracy_static.dat", "accuracy_static.gp",
                        "accuracy_simulation.dat", "accuracy_simulation.gp", "accuracy_static.png",
                        "accuracy_simulation.png"})
  {
    EXPECT_TRUE(fs::exists(out_ / f)) << f;
    EXPECT_NE(result_.out.find(f), std::string::npos) << "path not printed: " << f;
  }
  // PNG signature
  EXPECT_EQ(clitest::readFile(out_ / "accuracy_static.png").substr(1, 3), "PNG");
  // no temporary left behind
  for(const auto & e : fs::directory_iterator(out_)) EXPECT_NE(e.path().filename().string().front(), '.');
}

/// Every variant's error is finite and within its stated bound.
static void checkBounds(const clitest::Result & result_, const fs::path & out_)
{
  ASSERT_EQ(result_.code, 0) << result_.err;
  const auto rows = readCsv(clitest::readFile(out_ / "accuracy.csv"));
  int staticRows = 0, simRows = 0;
  std::map<std::string, double> maxErr; // "implementation scalar function" (own reference) -> max error
  for(const auto & r : rows)
  {
    SCOPED_TRACE(r.at("variant"));
    const double err = std::stod(r.at("max_error"));
    EXPECT_TRUE(std::isfinite(err));
    if(r.at("study") == "static")
    {
      ++staticRows;
      EXPECT_GT(std::stod(r.at("ns_per_call")), 0);
      if(r.at("bound").empty()) continue; // the modelling error of dropping velocity terms
      EXPECT_LE(err, std::stod(r.at("bound")));
      EXPECT_EQ(r.at("within_bound"), "1");
      maxErr[r.at("implementation") + " " + r.at("scalar") + " " + r.at("function")] = err;
    }
    else
    {
      ++simRows;
      EXPECT_GT(std::stod(r.at("wall_s_per_sim_s")), 0);
      if(r.at("integrator") == "rk4")
      {
        EXPECT_LT(err, 1e-6); // 1e-4..1e-2 steps over 0.2 s
      }
    }
  }
  // 9 functions (7 + the two derivatives) x (generated float, generated double, runtime double) + 3 gravity-as-bias rows
  EXPECT_EQ(staticRows, 9 * 3 + 3);
  EXPECT_EQ(simRows, 3 * 7);
  // Double is at least 1e5 times more accurate than float, generated as runtime (same algorithms).
  for(const char * f : {"fk", "id", "nle", "gravity", "mass_matrix", "fd_aba", "fd_crba", "id_derivatives", "fd_derivatives"})
  {
    SCOPED_TRACE(f);
    const double gf = maxErr.at(std::string("generated float ") + f), gd = maxErr.at(std::string("generated double ") + f),
                 rd = maxErr.at(std::string("runtime double ") + f);
    EXPECT_LT(gd, 1e-5 * gf);
    EXPECT_LT(rd, 1e-5 * gf);
    EXPECT_GT(gf, 1e-9); // float really ran in float
  }
}

/// gravity_torques against ID(q, alpha, 0) at |alpha| up to 2 rad/s: far from rounding.
static void checkVelocityTermsMatter(const clitest::Result & result_, const fs::path & out_)
{
  // gravity_torques against ID(q, alpha, 0) at |alpha| up to 2 rad/s: far from rounding.
  ASSERT_EQ(result_.code, 0) << result_.err;
  for(const auto & r : readCsv(clitest::readFile(out_ / "accuracy.csv")))
  {
    if(r.at("function") == "gravity" && r.at("reference") == "nle")
    {
      EXPECT_GT(std::stod(r.at("max_error")), 1e-3);
    }
  }
}

// One study run (the driver compile takes seconds), three checks.
TEST_F(AccuracyStudy, DoublePendulum)
{
  checkFiles(result_, out_);
  checkBounds(result_, out_);
  checkVelocityTermsMatter(result_, out_);
}

TEST_F(CliTest, AccuracyBadRobotIsOneLineAndWritesNothing)
{
  const auto r = clitest::rbdgen({"accuracy", std::string(RBDGEN_CLI_BAD_DIR) + "/missing_link.urdf", "--out", "out"}, dir());
  EXPECT_TRUE(clitest::isOneLineError(r));
  EXPECT_NE(r.err.find("missing_link.urdf"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir() / "out"));
}

TEST_F(CliTest, AccuracyUnwritableOutIsOneLineAndWritesNothing)
{
  clitest::writeFile(dir() / "file", "x");
  const auto r = clitest::rbdgen({"accuracy", robot("pendulum").string(), "--out", "file/sub"}, dir());
  EXPECT_TRUE(clitest::isOneLineError(r));
  EXPECT_NE(r.err.find("file/sub"), std::string::npos) << r.err;
  EXPECT_EQ(clitest::listTree(dir()), std::vector<std::string>{"file"});
  const auto r2 = clitest::rbdgen({"accuracy", robot("pendulum").string(), "--out", "file"}, dir());
  EXPECT_TRUE(clitest::isOneLineError(r2));
  EXPECT_EQ(clitest::readFile(dir() / "file"), "x");
}

TEST_F(CliTest, AccuracyBadCompilerIsOneLineAndWritesNothing)
{
  const auto r = clitest::rbdgen({"accuracy", robot("pendulum").string(), "--out", "out", "--states", "3", "--no-simulation",
                                  "--cxx", "/nonexistent/c++"},
                                 dir());
  EXPECT_TRUE(clitest::isOneLineError(r));
  EXPECT_NE(r.err.find("/nonexistent/c++"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir() / "out"));
}
