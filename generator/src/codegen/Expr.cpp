#include "Expr.h"
#include "HomeInSlots.h"
#include "InlineSingleUse.h"
#include "SinCosBatch.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <cctype>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rbdgen::cg
{

Scalar Scalar::constant(double v)
{
  Scalar s;
  s.isConst_ = true;
  s.value_ = v == 0.0 ? 0.0 : v; // no negative zero in emitted text
  return s;
}

Scalar Scalar::var(std::string name)
{
  Scalar s;
  s.isConst_ = false;
  s.name_ = std::move(name);
  return s;
}

Scalar Scalar::named(double v, std::string label)
{
  Scalar s = constant(v);
  if(v != 0.0 && std::abs(v) != 1.0) s.label_ = std::move(label);
  return s;
}

std::string Block::number(double v)
{
  if(v == 0.0) return "0";
  if(v == std::floor(v) && std::abs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  // Shortest text that round-trips, for readability.
  for(int p = 1; p <= 17; ++p)
  {
    char s[40];
    std::snprintf(s, sizeof s, "%.*g", p, v);
    if(std::strtod(s, nullptr) == v)
    {
      std::snprintf(buf, sizeof buf, "%s", s);
      break;
    }
  }
  return buf;
}

std::string Block::literal(double v)
{
  return "S(" + number(v) + ")";
}

std::string Block::text(const Scalar & s)
{
  if(!s.isConst()) return s.name();
  return s.label().empty() ? literal(s.value()) : "S(" + s.label() + ")";
}

namespace
{

// Fold constant factors into the coefficient and drop zero terms; merge the lone constants into
// `constant`. A named constant stays a factor of its term (printed by name) when it is the term's
// only constant factor besides a coefficient of +-1 and the term reads a variable; `constantLabel`
// is the label of `constant` when one named constant (times +-1) is all of it.
std::vector<Term> normalise(const std::vector<Term> & terms, double & constant, std::string * constantLabel = nullptr)
{
  std::vector<Term> out;
  constant = 0.0;
  int constants = 0;
  std::string label;
  for(const Term & t : terms)
  {
    Term n;
    n.coef = t.coef;
    const Scalar * named = nullptr;
    int otherConstants = 0; // constant factors other than the named one and +-1
    double sign = t.coef;
    for(const Scalar & f : t.factors)
    {
      if(f.isConst())
      {
        n.coef *= f.value();
        if(!f.label().empty() && !named) named = &f;
        else if(std::abs(f.value()) == 1.0) sign *= f.value();
        else ++otherConstants;
      }
      else n.factors.push_back(f);
    }
    if(n.coef == 0.0) continue;
    const bool byName = named && otherConstants == 0 && std::abs(sign) == 1.0;
    Scalar positive; // the named factor with a label that does not start with '-' (the sign moved)
    if(byName)
    {
      const bool negated = named->label()[0] == '-';
      positive = negated ? Scalar::named(-named->value(), named->label().substr(1)) : *named;
      if(negated) sign = -sign;
    }
    if(n.factors.empty())
    {
      constant += n.coef;
      ++constants;
      label = byName ? (sign < 0 ? "-" : "") + positive.label() : "";
    }
    else
    {
      if(byName)
      {
        n.coef = sign;
        n.factors.insert(n.factors.begin(), positive);
      }
      out.push_back(n);
    }
  }
  if(constantLabel) *constantLabel = constants == 1 ? label : "";
  return out;
}

std::string factorText(const Scalar & f)
{
  return f.isConst() ? Block::text(f) : f.name();
}

template<typename F>
void forEachIdentifier(const std::string & text, F && f)
{
  auto isStart = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; };
  auto isPart = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for(std::size_t i = 0; i < text.size();)
  {
    if(isStart(text[i]) && (i == 0 || !isPart(text[i - 1])))
    {
      std::size_t j = i;
      while(j < text.size() && isPart(text[j])) ++j;
      f(text.substr(i, j - i));
      i = j;
    }
    else ++i;
  }
}

} // namespace

namespace
{

// c as the last operand of a sum: ` + S(0.5)`, ` - S(0.5)`, ` + S(model::j1.rx)`, ` - S(model::j1.rx)`
std::string constantOperand(double c, const std::string & label)
{
  if(label.empty()) return (c < 0 ? " - " : " + ") + Block::literal(std::abs(c));
  const bool negated = label[0] == '-';
  return (negated ? " - " : " + ") + std::string("S(") + (negated ? label.substr(1) : label) + ")";
}

} // namespace

std::string Block::text(const std::vector<Term> & terms)
{
  double c = 0.0;
  std::string cLabel;
  const std::vector<Term> ts = normalise(terms, c, &cLabel);
  std::string s;
  for(const Term & t : ts)
  {
    std::string factors;
    for(const Scalar & f : t.factors) factors += (factors.empty() ? "" : " * ") + factorText(f);
    const double a = std::abs(t.coef);
    const std::string mag = a == 1.0 ? factors : literal(a) + " * " + factors;
    if(s.empty()) s = (t.coef < 0 ? "-" : "") + mag;
    else s += (t.coef < 0 ? " - " : " + ") + mag;
  }
  if(c != 0.0 || s.empty())
  {
    if(s.empty()) s = cLabel.empty() ? literal(c) : "S(" + cLabel + ")";
    else s += constantOperand(c, cLabel);
  }
  return s;
}

std::string Block::fresh(const std::string & hint)
{
  std::string base = hint.empty() ? std::string("t") : hint;
  std::string name = base;
  int k = 1;
  while(std::find(taken_.begin(), taken_.end(), name) != taken_.end()) name = base + "_" + std::to_string(k++);
  taken_.push_back(name);
  return name;
}

Scalar Block::sum(const std::vector<Term> & terms, const std::string & hint)
{
  double c = 0.0;
  std::string cLabel;
  const std::vector<Term> ts = normalise(terms, c, &cLabel);
  if(ts.empty()) return cLabel.empty() ? Scalar::constant(c) : Scalar::named(c, cLabel);
  if(ts.size() == 1 && c == 0.0 && ts[0].coef == 1.0 && ts[0].factors.size() == 1) return ts[0].factors[0];
  for(const Term & t : ts)
  {
    mults_ += static_cast<long>(t.factors.size()) - 1 + (std::abs(t.coef) == 1.0 ? 0 : 1);
  }
  adds_ += static_cast<long>(ts.size()) - 1 + (c != 0.0 ? 1 : 0);
  const std::string name = fresh(hint);
  lines_.push_back("const S " + name + " = " + text(ts) + (c != 0.0 ? constantOperand(c, cLabel) : "") + ";");
  return Scalar::var(name);
}

Scalar Block::def(const std::string & rhs, const std::string & hint)
{
  ++calls_;
  const std::string name = fresh(hint);
  lines_.push_back("const S " + name + " = " + rhs + ";");
  return Scalar::var(name);
}

void Block::line(const std::string & text)
{
  lines_.push_back(text);
}

std::string Block::str(const std::string & indent) const
{
  // Dead-code elimination, from the last line up.
  std::vector<bool> keep(lines_.size(), true);
  std::set<std::string> used;
  for(std::size_t k = lines_.size(); k-- > 0;)
  {
    const std::string & l = lines_[k];
    std::string rhs = l;
    // `const S x = ...;` and a shared pass's results `[[maybe_unused]] const auto x = detail::f<S>(...);`
    // (pure, always-inline functions) are kept only when x is read
    const std::string passResult = "[[maybe_unused]] const auto ";
    const bool pass = l.rfind(passResult, 0) == 0 && l.find(" = detail::") != std::string::npos && l.find("<S>(") != std::string::npos;
    if(l.rfind("const S ", 0) == 0 || pass)
    {
      const auto eq = l.find(" = ");
      const std::size_t from = pass ? passResult.size() : 8;
      const std::string name = l.substr(from, eq - from);
      if(!used.count(name))
      {
        keep[k] = false;
        continue;
      }
      rhs = l.substr(eq + 3);
    }
    forEachIdentifier(rhs, [&](std::string id) { used.insert(std::move(id)); });
  }
  std::vector<std::string> kept;
  for(std::size_t k = 0; k < lines_.size(); ++k)
    if(keep[k]) kept.push_back(lines_[k]);
  if(batchSinCos_) kept = rbdgen::cg::batchSinCos(kept);
  kept = inlineSingleUse(kept, indent.size() < 120 ? 120 - indent.size() : 0);
  if(!homeArrays_.empty()) kept = homeInSlots(kept, homeArrays_, readByElement_, changedInPlace_);
  // A section comment (`// j3: ...`) directly followed by the same comment of the next joint heads
  // no code (its statements were shared or folded away): dropped.
  auto afterTag = [](const std::string & l) { return l.substr(std::min(l.find(' ', 3), l.size())); };
  std::vector<std::string> sections;
  for(std::size_t k = 0; k < kept.size(); ++k)
  {
    const bool comment = kept[k].rfind("// ", 0) == 0;
    if(comment && k + 1 < kept.size() && kept[k + 1].rfind("// ", 0) == 0 && afterTag(kept[k]) == afterTag(kept[k + 1]))
      continue;
    sections.push_back(kept[k]);
  }
  kept = std::move(sections);
  std::string out;
  for(const std::string & l : kept) out += indent + l + "\n";
  return out;
}

void stashScalars(Block & b, const std::string & array, int k, const std::vector<Scalar *> & e)
{
  for(std::size_t i = 0; i < e.size(); ++i)
  {
    if(e[i]->isConst()) continue;
    const std::string slot = array + "[" + std::to_string(k) + "][" + std::to_string(i) + "]";
    b.line(slot + " = " + Block::text(*e[i]) + ";");
    *e[i] = Scalar::var(slot);
  }
}

Scalar add(Block & b, const Scalar & x, const Scalar & y, const std::string & hint)
{
  return b.sum({Term{1.0, {x}}, Term{1.0, {y}}}, hint);
}

Scalar sub(Block & b, const Scalar & x, const Scalar & y, const std::string & hint)
{
  return b.sum({Term{1.0, {x}}, Term{-1.0, {y}}}, hint);
}

Scalar mul(Block & b, const Scalar & x, const Scalar & y, const std::string & hint)
{
  return b.sum({Term{1.0, {x, y}}}, hint);
}

Scalar neg(Block & b, const Scalar & x, const std::string & hint)
{
  return b.sum({Term{-1.0, {x}}}, hint);
}

} // namespace rbdgen::cg
