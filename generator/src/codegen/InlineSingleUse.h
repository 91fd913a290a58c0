#pragma once
// Single-use temporaries folded into the one expression that reads them. A statement
// `const S t = <rhs>;` whose t is read exactly once, by a line at most 32 lines below with nothing
// written in between that <rhs> reads (so <rhs> reads the same values there), is
// removed and <rhs> substituted for t, parenthesised unless C++ precedence already evaluates it as
// one operand in the same order: `a + t` with t = `b * c` is `a + b * c`, `t * d` is `b * c * d`
// ((b * c) * d), `t + d` with t = `a - b` is `a - b + d`; `d * t`, `d - t` and `d + t` with t a sum
// keep the parentheses. Every operation is the same, in the same order, on the same operands: the
// emitted arithmetic is unchanged (clang++ may contract more a * b + c into FMAs within one
// statement). Calls (`std::`, `detail::`) stay named; a substitution that would make the line longer
// than maxLength characters is not made.

#include <string>
#include <vector>

namespace rbdgen::cg
{

std::vector<std::string> inlineSingleUse(const std::vector<std::string> & lines, std::size_t maxLength = 120);

} // namespace rbdgen::cg
