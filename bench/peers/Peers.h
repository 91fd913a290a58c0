#pragma once
// Peer libraries in the same run: each checks itself against the runtime on a few pool states
// (CheckLog entries "kdl", "mujoco") and registers only the cells that agree.

#include "../common/BenchCase.h"
#include "../common/Checks.h"

namespace rbdbench
{
void registerKdl(const BenchCase & c, CheckLog & log);    ///< no-op without KDL (RBDGEN_BENCH_HAVE_KDL)
void registerMujoco(const BenchCase & c, CheckLog & log); ///< no-op without MuJoCo (RBDGEN_BENCH_HAVE_MUJOCO)

inline void registerPeers(const BenchCase & c, CheckLog & log)
{
  registerKdl(c, log);
  registerMujoco(c, log);
}

/// Number of pool states the peers are checked on.
constexpr std::size_t kPeerChecked = 8;
} // namespace rbdbench
