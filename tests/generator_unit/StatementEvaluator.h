#pragma once
// An evaluator of the straight-line C++ subset the generator emits, written from the language's
// rules (precedence, left associativity, unary minus), independent of the post-passes over the
// emitted lines (InlineSingleUse, HomeInSlots) that the tests run it on.

#include <cctype>
#include <cstdlib>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace rbdgen::test
{

// Recursive descent over: expr = term {(+|-) term}; term = unary {(*|/) unary};
// unary = -unary | primary; primary = name | name(i, j) | name[i] | S(literal) | (expr).
class Evaluator
{
public:
  explicit Evaluator(std::map<std::string, double> & vars) : vars_(vars) {}

  double eval(const std::string & text)
  {
    s_ = text;
    i_ = 0;
    const double v = expr();
    skip();
    if(i_ != s_.size()) throw std::runtime_error("trailing text in '" + text + "'");
    return v;
  }

private:
  void skip()
  {
    while(i_ < s_.size() && s_[i_] == ' ') ++i_;
  }
  double expr()
  {
    double v = term();
    for(skip(); i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-'); skip())
    {
      const char op = s_[i_++];
      const double r = term();
      v = op == '+' ? v + r : v - r;
    }
    return v;
  }
  double term()
  {
    double v = unary();
    for(skip(); i_ < s_.size() && (s_[i_] == '*' || s_[i_] == '/'); skip())
    {
      const char op = s_[i_++];
      const double r = unary();
      v = op == '*' ? v * r : v / r;
    }
    return v;
  }
  double unary()
  {
    skip();
    if(s_[i_] == '-')
    {
      ++i_;
      return -unary();
    }
    return primary();
  }
  double primary()
  {
    skip();
    if(s_[i_] == '(')
    {
      ++i_;
      const double v = expr();
      skip();
      ++i_; // ')'
      return v;
    }
    std::size_t j = i_;
    while(j < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[j])) || s_[j] == '_')) ++j;
    std::string name = s_.substr(i_, j - i_);
    i_ = j;
    if(name == "S")
    {
      ++i_; // '('
      char * end = nullptr;
      const double v = std::strtod(s_.c_str() + i_, &end);
      i_ = static_cast<std::size_t>(end - s_.c_str()) + 1; // ')'
      return v;
    }
    if(i_ < s_.size() && s_[i_] == '(')
    {
      const std::size_t k = s_.find(')', i_);
      name += s_.substr(i_, k - i_ + 1);
      i_ = k + 1;
    }
    while(i_ < s_.size() && s_[i_] == '[')
    {
      const std::size_t k = s_.find(']', i_);
      name += s_.substr(i_, k - i_ + 1);
      i_ = k + 1;
    }
    const auto it = vars_.find(name);
    if(it == vars_.end()) throw std::runtime_error("unknown " + name);
    return it->second;
  }

  std::map<std::string, double> & vars_;
  std::string s_;
  std::size_t i_ = 0;
};

// Runs `const S x = e;`, `out[k] = e;`, `out[k] -= e;`, `m(i, j) = e;` and `a[i][j] = e;` lines
// (other lines, e.g. declarations, are skipped); returns every value written to out[] and m(), in
// order, and the final value of every name and slot in `final` when given.
inline std::vector<double> run(const std::vector<std::string> & lines, std::map<std::string, double> vars,
                               std::map<std::string, double> * final = nullptr)
{
  Evaluator ev(vars);
  std::vector<double> written;
  for(const std::string & l : lines)
  {
    const auto eq = l.find(" = "), minusEq = l.find(" -= ");
    if(l.rfind("//", 0) == 0 || (eq == std::string::npos && minusEq == std::string::npos)) continue;
    const bool sub = minusEq != std::string::npos && minusEq < eq;
    const std::size_t at = sub ? minusEq : eq;
    std::string lhs = l.substr(0, at), rhs = l.substr(at + (sub ? 4 : 3));
    rhs.pop_back(); // ';'
    const double v = ev.eval(rhs);
    if(lhs.rfind("const S ", 0) == 0) lhs = lhs.substr(8);
    double & dst = vars[lhs];
    dst = sub ? dst - v : v;
    if(lhs.rfind("out", 0) == 0 || lhs.rfind("m(", 0) == 0) written.push_back(dst);
  }
  if(final) *final = vars;
  return written;
}

} // namespace rbdgen::test
