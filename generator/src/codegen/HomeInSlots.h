#pragma once
// Values that are copied into an array get their slot as their home. A top-level statement
// `const S x = <rhs>;` whose value a later top-level line copies into a slot of one of the given
// arrays (`a[i][j] = x;`, `a(i, j) = x;`), a slot no other line writes, becomes `a[i][j] = <rhs>;`;
// that copy is dropped and every other read of x reads the slot (further copies of x copy the
// slot). The array's declaration moves up to the first statement that writes a home in it when it
// came later. The arithmetic is unchanged (each value is computed by the same expression, once);
// what goes is the copy: in a body of thousands of values, x was spilled to the stack where it was
// computed and read back for the copy, or kept in a register across the statements in between.
// The arrays are the inputs of out-of-line kernels and columns (the derivatives' lanes): written by
// assignments, or by a call only in slots no copy writes (padding lanes and rows). A further copy of a homed value into an array of
// `readByElement` (read slot by slot, never as a whole by a kernel) goes too: the reads of that
// slot read the home. An array of `changedInPlace` has its slots changed after the copies by lines
// that name the array otherwise (the LTDL factorisation's row updates): a value read at or after
// the first such line following its copy is not homed there (its reads would see the changed slot).

#include <set>
#include <string>
#include <vector>

namespace rbdgen::cg
{

std::vector<std::string> homeInSlots(const std::vector<std::string> & lines, const std::set<std::string> & arrays,
                                     const std::set<std::string> & readByElement = {},
                                     const std::set<std::string> & changedInPlace = {});

} // namespace rbdgen::cg
