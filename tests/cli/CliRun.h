#pragma once
// Helpers to run the built rbdgen executable in a scratch directory and look at what it did.

#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace clitest
{
namespace fs = std::filesystem;

inline std::string readFile(const fs::path & p)
{
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeFile(const fs::path & p, const std::string & text)
{
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
}

/// 'text' for /bin/sh, single quotes escaped.
inline std::string shellQuote(const std::string & s)
{
  std::string q = "'";
  for(char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct Result
{
  int code = -1;   ///< exit status (-1: did not exit normally)
  std::string out; ///< stdout
  std::string err; ///< stderr
};

/// Run `cmd` (a shell command) in directory cwd, capturing stdout, stderr and the exit status.
inline Result runShell(const std::string & cmd, const fs::path & cwd)
{
  const fs::path outF = cwd / ".cli_stdout", errF = cwd / ".cli_stderr";
  const std::string line = "cd " + shellQuote(cwd.string()) + " && " + cmd + " >" + shellQuote(outF.string()) + " 2>" +
                           shellQuote(errF.string());
  const int status = std::system(line.c_str());
  Result r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = readFile(outF);
  r.err = readFile(errF);
  fs::remove(outF);
  fs::remove(errF);
  return r;
}

/// Run the rbdgen under test with these arguments, in cwd.
inline Result rbdgen(const std::vector<std::string> & args, const fs::path & cwd)
{
  std::string cmd = shellQuote(RBDGEN_EXE);
  for(const auto & a : args) cmd += " " + shellQuote(a);
  return runShell(cmd, cwd);
}

/// sha256 of a file by coreutils' sha256sum (independent of rbdgen's own SHA-256).
inline std::string sha256sum(const fs::path & p)
{
  const std::string cmd = "sha256sum " + shellQuote(p.string());
  FILE * f = popen(cmd.c_str(), "r");
  if(!f) return "";
  char buf[256] = {};
  const std::size_t n = std::fread(buf, 1, sizeof(buf) - 1, f);
  pclose(f);
  const std::string line(buf, n);
  return line.substr(0, line.find(' '));
}

/// Every file and directory under dir (relative paths, sorted); empty if dir does not exist.
inline std::vector<std::string> listTree(const fs::path & dir)
{
  std::vector<std::string> v;
  if(!fs::exists(dir)) return v;
  for(const auto & e : fs::recursive_directory_iterator(dir)) v.push_back(fs::relative(e.path(), dir).string());
  std::sort(v.begin(), v.end());
  return v;
}

inline int countLines(const std::string & s)
{
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

/// A fresh directory under the system temporary directory, removed with everything in it.
class TempDir
{
public:
  TempDir()
  {
    std::random_device rd;
    for(int attempt = 0; attempt < 100; ++attempt)
    {
      path_ = fs::temp_directory_path() / ("rbdgen_cli_" + std::to_string(rd()));
      if(fs::create_directory(path_)) return;
    }
    throw std::runtime_error("cannot create a temporary directory");
  }
  ~TempDir()
  {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir &) = delete;
  TempDir & operator=(const TempDir &) = delete;
  const fs::path & path() const { return path_; }

private:
  fs::path path_;
};

/// One scratch directory per test.
class CliTest : public ::testing::Test
{
protected:
  TempDir tmp;
  const fs::path & dir() const { return tmp.path(); }
  static fs::path robot(const std::string & name) { return fs::path(RBDGEN_SOURCE_DIR) / "robots" / (name + ".urdf"); }
};

/// An error as the CLI must report it: non-zero exit, nothing on stdout, exactly one line on stderr.
inline ::testing::AssertionResult isOneLineError(const Result & r)
{
  if(r.code == 0) return ::testing::AssertionFailure() << "exit code 0; stderr: " << r.err;
  if(r.code < 0) return ::testing::AssertionFailure() << "did not exit normally (crash?); stderr: " << r.err;
  if(!r.out.empty()) return ::testing::AssertionFailure() << "stdout not empty: " << r.out;
  if(r.err.empty() || r.err.back() != '\n' || countLines(r.err) != 1 || r.err.size() < 10)
    return ::testing::AssertionFailure() << "stderr is not exactly one line: [" << r.err << "]";
  return ::testing::AssertionSuccess();
}

} // namespace clitest
