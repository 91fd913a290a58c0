#pragma once
// Peer libraries in the same run: each checks itself against the runtime on a few pool states
// (CheckLog entries "kdl", "mujoco", "pinocchio") and registers only the cells that agree.

#include "../common/BenchCase.h"
#include "../common/Checks.h"

namespace rbdbench
{
void registerKdl(const BenchCase & c, CheckLog & log);    ///< no-op without KDL (RBDGEN_BENCH_HAVE_KDL)
void registerMujoco(const BenchCase & c, CheckLog & log); ///< no-op without MuJoCo (RBDGEN_BENCH_HAVE_MUJOCO)
/// Pinocchio, header-only (library rbdgen_bench_pinocchio): no-op unless configured with
/// -DRBDGEN_PINOCCHIO_SOURCE_DIR=DIR (RBDGEN_BENCH_HAVE_PINOCCHIO).
void registerPinocchio(const BenchCase & c, CheckLog & log);

inline void registerPeers(const BenchCase & c, CheckLog & log)
{
  registerKdl(c, log);
  registerMujoco(c, log);
  registerPinocchio(c, log);
}

/// Number of pool states the peers are checked on.
constexpr std::size_t kPeerChecked = 8;
} // namespace rbdbench
