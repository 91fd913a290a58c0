#pragma once
// sin and cos of every joint angle of a function at once: the emitted `std::sin(q[i])` /
// `std::cos(q[i])` statements become one call of the header's detail::sincos_all (a branch-free
// polynomial both g++ and clang++ vectorise), instead of one libm call per angle.

#include <string>
#include <vector>

namespace rbdgen::cg
{

/// Rewrite statements `const S <name> = std::sin(q[<i>]);` (and cos) into reads `sincos.s[k]` /
/// `sincos.c[k]` of `const auto sincos = detail::sincos_all(sincos_q);`, which goes at the top of
/// the body with `const S sincos_q[K] = {q[..], ...};`. Other lines unchanged.
std::vector<std::string> batchSinCos(const std::vector<std::string> & lines);

} // namespace rbdgen::cg
