#pragma once
// Agreement checks run at start-up: the largest error of each implementation x algorithm against
// the runtime over a few states. An implementation is timed for an algorithm only if it agrees.

#include <string>
#include <vector>

namespace rbdbench
{

/// Algorithms, in table order. Names are those of the benchmark names and the results table.
extern const std::vector<std::string> kAlgorithms;

struct CheckResult
{
  std::string impl, algo;
  double maxErr = 0; ///< max over the checked states of relErr(impl, runtime)
  double tol = 0;
  std::string note;  ///< why the cell is n/a, or what exactly is compared
  bool modelDiffers = false; ///< the peer had to change the model (a disagreement is expected, not a failure)
  bool ok() const { return maxErr <= tol; }
};

class CheckLog
{
public:
  void add(const std::string & impl, const std::string & algo, double maxErr, double tol, const std::string & note = "",
           bool modelDiffers = false);
  /// Was (impl, algo) checked and within its tolerance?
  bool agrees(const std::string & impl, const std::string & algo) const;
  const std::vector<CheckResult> & results() const { return results_; }
  /// One line per check on stdout, and benchmark context entries "check/<impl>/<algo>".
  void publish(const std::string & robot) const;
  /// Every check agrees, except those flagged modelDiffers.
  bool allOk() const;

private:
  std::vector<CheckResult> results_;
};

} // namespace rbdbench
