#pragma once
// Symbolic scalars for code emission. A Scalar is either a constant known at generation time or
// the name of a local in the emitted code. Every operation folds constants (0, ±1, literals), so a
// joint about z, an identity fixed transform or a zero centre of mass cost nothing at run time:
// axis specialisation and constant folding fall out of the arithmetic.
//
// A constant may carry a name (Scalar::named: a model parameter, e.g. `model::j2.ry`): it is
// printed `S(name)` where it is read as it is (a factor of a product whose other constant factors
// are +-1, or alone); once combined with other constants it folds to a literal like any other.

#include <set>
#include <string>
#include <vector>

namespace rbdgen::cg
{

class Scalar
{
public:
  Scalar() = default;
  static Scalar constant(double v);
  static Scalar var(std::string name);
  /// A constant printed as `S(label)` (label: a C++ expression of value v, e.g. `model::j2.ry` or
  /// `-model::j2.ry`); 0 and +-1 stay plain constants (they fold away).
  static Scalar named(double v, std::string label);

  bool isConst() const { return isConst_; }
  double value() const { return value_; }
  /// The variable's name (empty for a constant).
  const std::string & name() const { return name_; }
  /// A named constant's label (empty otherwise).
  const std::string & label() const { return label_; }
  bool isZero() const { return isConst_ && value_ == 0.0; }

private:
  bool isConst_ = true;
  double value_ = 0.0;
  std::string name_;
  std::string label_;
};

/// c * f1 * f2 * ... (constant factors are folded into c).
struct Term
{
  double coef = 1.0;
  std::vector<Scalar> factors;
};

/// A function body being emitted: a list of `const S name = expr;` statements.
class Block
{
public:
  /// A statement `const S <fresh name> = sum of terms;`, or a constant / an existing name when
  /// the sum folds to one. Names are `<hint>` (made unique with a suffix when taken).
  Scalar sum(const std::vector<Term> & terms, const std::string & hint);
  /// A statement with a verbatim right-hand side (e.g. `std::sin(q[3])`).
  Scalar def(const std::string & rhs, const std::string & hint);
  /// A verbatim line (comments, output assignments).
  void line(const std::string & text);
  void comment(const std::string & text) { line("// " + text); }

  /// C++ text of a scalar: a name, `S(label)` for a named constant, or a literal `S(0.25)`.
  static std::string text(const Scalar & s);
  /// C++ text of a sum of terms (no statement), "S(0)" when empty.
  static std::string text(const std::vector<Term> & terms);
  static std::string literal(double v);
  /// The shortest decimal text that reads back as v (no `S(...)`): `0.25`, `-3`, `1e-12`.
  static std::string number(double v);

  const std::vector<std::string> & lines() const { return lines_; }
  /// Statements joined with the given indentation; unused locals are removed first, then single-use
  /// temporaries are folded into the expression that reads them (InlineSingleUse.h).
  std::string str(const std::string & indent) const;
  /// Floating-point operations emitted so far (multiplications, additions, other calls).
  long mults() const { return mults_; }
  long adds() const { return adds_; }
  long calls() const { return calls_; }
  /// Emit the sin/cos of all joint angles as one vectorised call (default; see SinCosBatch.h).
  void setBatchSinCos(bool on) { batchSinCos_ = on; }
  /// Values copied into this array's slots get their slot as home (HomeInSlots.h): for the arrays
  /// written by assignments only (the inputs of out-of-line kernels). readByElement: the array is
  /// read slot by slot only (never whole by a kernel), so a copy of a value homed elsewhere goes.
  /// changedInPlace: lines after the copies change its slots (the LTDL factors): a value read after
  /// the first such line keeps its own name.
  void homeCopiesIn(const std::string & array, bool readByElement = false, bool changedInPlace = false)
  {
    homeArrays_.insert(array);
    if(readByElement) readByElement_.insert(array);
    if(changedInPlace) changedInPlace_.insert(array);
  }

private:
  std::string fresh(const std::string & hint);
  std::vector<std::string> lines_;
  std::vector<std::string> taken_;
  long mults_ = 0, adds_ = 0, calls_ = 0;
  bool batchSinCos_ = true;
  std::set<std::string> homeArrays_, readByElement_, changedInPlace_;
};

/// Stores the non-constant scalars *e[i] in array[k][i] (`array[k][i] = value;`) and replaces them by
/// those slots: long-lived values moved into an array (the derivatives' stashes, the RNEA's forces).
void stashScalars(Block & b, const std::string & array, int k, const std::vector<Scalar *> & e);

/// Scalar helpers built on Block::sum.
Scalar add(Block & b, const Scalar & x, const Scalar & y, const std::string & hint);
Scalar sub(Block & b, const Scalar & x, const Scalar & y, const std::string & hint);
Scalar mul(Block & b, const Scalar & x, const Scalar & y, const std::string & hint);
Scalar neg(Block & b, const Scalar & x, const std::string & hint);

/// Calls of the header's detail::Lanes<S> (templates/detail_lanes.hpp.in) for the operations that are
/// not arithmetic: on one value the plain expression, on a pack of states (batch.hpp) every lane.
inline std::string lanesSqrt(const std::string & x) { return "detail::Lanes<S>::sqrt(" + x + ")"; }
inline std::string lanesSelect(const std::string & mask, const std::string & a, const std::string & b)
{
  return "detail::Lanes<S>::select(" + mask + ", " + a + ", " + b + ")";
}
inline std::string lanesBoth(const std::string & a, const std::string & b) { return "detail::Lanes<S>::both(" + a + ", " + b + ")"; }

} // namespace rbdgen::cg
