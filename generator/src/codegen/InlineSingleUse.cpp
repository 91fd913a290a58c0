#include "InlineSingleUse.h"

#include "StatementText.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace rbdgen::cg
{

namespace
{

using text::codeOf;
using text::forEachLocal;
using text::isPart;
using text::isStart;
using text::parseDef;

/// Whether e calls a qualified function (`std::sin(`, `detail::Lanes<S>::sqrt(`): a qualified name
/// followed by `(` or `<`; a named model constant (`S(model::j3.rz)`) is not a call.
bool callsQualified(const std::string & e)
{
  for(std::size_t p = e.find("::"); p != std::string::npos; p = e.find("::", p + 2))
  {
    std::size_t j = p + 2;
    while(j < e.size() && isPart(e[j])) ++j;
    if(j < e.size() && (e[j] == '(' || e[j] == '<')) return true;
    if(p > 0 && e[p - 1] == '>') return true; // Lanes<S>::...
  }
  return false;
}

/// Lines a read can move across: declarations (they write nothing already declared) and comments.
bool isTransparent(const std::string & l)
{
  return l.rfind("const ", 0) == 0 || l.rfind("[[maybe_unused]] const ", 0) == 0 || l.rfind("//", 0) == 0;
}

/// The object an assignment `x = ...;`, `x(i, j) -= ...;`, `x[i] = ...;`, `x.m = ...;` writes
/// ("x"), or "" for any other line (a call, a loop, a brace: nothing can move across it).
std::string writtenObject(const std::string & l)
{
  // detail::set_pose(x..., ...) and detail::set_motion(x..., ...) write their first argument only
  for(const std::string setter : {"detail::set_pose(", "detail::set_motion("})
    if(l.rfind(setter, 0) == 0)
    {
      std::size_t j = setter.size();
      while(j < l.size() && isPart(l[j])) ++j;
      return l.substr(setter.size(), j - setter.size());
    }
  if(l.empty() || !isStart(l[0])) return "";
  std::size_t i = 0;
  while(i < l.size() && isPart(l[i])) ++i;
  const std::string base = l.substr(0, i);
  for(const char * kw : {"for", "if", "while", "switch", "case", "do", "else", "return", "default", "break"})
    if(base == kw) return "";
  int depth = 0;
  for(; i < l.size(); ++i)
  {
    const char c = l[i];
    if(c == '(' || c == '[') ++depth;
    else if(c == ')' || c == ']') --depth;
    else if(depth == 0 && c == '=') return i + 1 < l.size() && l[i + 1] != '=' ? base : "";
    else if(depth == 0 && !(c == ' ' || c == '.' || isPart(c) || c == '+' || c == '-' || c == '*' || c == '/')) return "";
  }
  return "";
}

/// Lines a value can be substituted into: one statement evaluated once, where it stands.
bool isPlainStatement(const std::string & l)
{
  for(const char * kw : {"for", "if", "while", "switch", "case", "do", "else", "return", "default"})
  {
    const std::string k(kw);
    if(l.rfind(k, 0) == 0 && (l.size() == k.size() || !isPart(l[k.size()]))) return false;
  }
  const std::string code = codeOf(l);
  return code.find('{') == std::string::npos && code.find('}') == std::string::npos && code.find('?') == std::string::npos;
}

enum class Kind { Atom, Product, Sum };

/// Shape of an expression at its top level (outside brackets).
Kind kindOf(const std::string & e)
{
  int depth = 0;
  bool product = false;
  for(std::size_t i = 0; i < e.size(); ++i)
  {
    const char c = e[i];
    if(c == '(' || c == '[') ++depth;
    else if(c == ')' || c == ']') --depth;
    else if(depth == 0 && i > 0 && e[i - 1] == ' ' && i + 1 < e.size() && e[i + 1] == ' ')
    {
      if(c == '+' || c == '-') return Kind::Sum;
      if(c == '*' || c == '/') product = true;
    }
  }
  return product ? Kind::Product : Kind::Atom;
}

enum class Left { Start, Binary, Unary, Mul, Other };
enum class Right { End, SumOp, MulOp, Other };

Left leftOf(const std::string & l, std::size_t p)
{
  std::size_t j = p;
  while(j > 0 && l[j - 1] == ' ') --j;
  if(j == 0) return Left::Other;
  const char a = l[j - 1];
  if(a == '=' || a == '(' || a == ',') return Left::Start;
  if(a == '-') return j == p ? Left::Unary : Left::Binary;
  if(a == '+') return Left::Binary;
  if(a == '*' || a == '/') return Left::Mul;
  return Left::Other;
}

Right rightOf(const std::string & l, std::size_t e)
{
  while(e < l.size() && l[e] == ' ') ++e;
  if(e == l.size()) return Right::Other;
  const char b = l[e];
  if(b == ';' || b == ')' || b == ',') return Right::End;
  if(b == '+' || b == '-') return Right::SumOp;
  if(b == '*' || b == '/') return Right::MulOp;
  return Right::Other;
}

/// Whether `rhs` substituted for the name at [p, e) of line l needs parentheses to be evaluated as
/// one operand, as the name was.
bool needsParentheses(const std::string & rhs, const std::string & l, std::size_t p, std::size_t e)
{
  const Left left = leftOf(l, p);
  const Right right = rightOf(l, e);
  if(left == Left::Other || right == Right::Other) return true;
  const bool negated = rhs[0] == '-';
  switch(kindOf(rhs))
  {
  case Kind::Atom:
    return negated && left != Left::Start;
  case Kind::Product:
    if(negated) return left != Left::Start;
    return left == Left::Mul;
  case Kind::Sum:
    return !(left == Left::Start && right != Right::MulOp);
  }
  return true;
}

std::size_t longestLine(const std::string & text)
{
  std::size_t best = 0, start = 0;
  for(std::size_t i = 0; i <= text.size(); ++i)
    if(i == text.size() || text[i] == '\n')
    {
      best = std::max(best, i - start);
      start = i + 1;
    }
  return best;
}

// A read moves at most this many lines down: moved far, a computation changes the order g++
// schedules a long body in (talos_reduced's inverse dynamics ran 7 % slower with any distance,
// as before the folding with 32; ur5's header is 2,668 lines with 32, 2,593 with any distance).
constexpr std::size_t kMaxDistance = 32;

} // namespace

std::vector<std::string> inlineSingleUse(const std::vector<std::string> & input, std::size_t maxLength)
{
  std::vector<std::string> lines = input;
  const std::size_t n = lines.size();

  // Defined names, and for each the number of reads and the line of the last one.
  std::map<std::string, std::size_t> defLine;
  for(std::size_t k = 0; k < n; ++k)
  {
    std::string name, rhs;
    if(parseDef(lines[k], name, rhs)) defLine.emplace(name, k);
  }
  std::map<std::string, int> reads;
  std::map<std::string, std::size_t> readLine;
  for(std::size_t k = 0; k < n; ++k)
  {
    std::string code = codeOf(lines[k]), name, rhs;
    const std::size_t from = parseDef(lines[k], name, rhs) ? code.find(" = ") + 3 : 0;
    code = code.substr(from);
    forEachLocal(code, [&](std::size_t i, std::size_t j) {
      const std::string id = code.substr(i, j - i);
      if(!defLine.count(id)) return;
      ++reads[id];
      readLine[id] = k;
    });
  }
  // What each line writes: nothing (a declaration or a comment), one object, or anything ("").
  std::vector<bool> transparent(n);
  std::vector<std::string> writes(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    transparent[k] = isTransparent(lines[k]);
    if(!transparent[k]) writes[k] = writtenObject(codeOf(lines[k]));
  }
  // A read moves from line k to line `use` when no line in between writes what it reads.
  auto canMove = [&](const std::string & rhs, std::size_t k, std::size_t use) {
    if(use - k > kMaxDistance) return false;
    std::vector<std::string> read;
    forEachLocal(rhs, [&](std::size_t i, std::size_t j) { read.push_back(rhs.substr(i, j - i)); });
    for(std::size_t m = k + 1; m < use; ++m)
    {
      if(transparent[m]) continue;
      if(writes[m].empty() || std::find(read.begin(), read.end(), writes[m]) != read.end()) return false;
    }
    return true;
  };

  std::vector<bool> removed(n, false);
  for(std::size_t k = 0; k < n; ++k)
  {
    std::string name, rhs;
    if(!parseDef(lines[k], name, rhs) || defLine[name] != k || reads[name] != 1) continue;
    if(rhs.empty() || callsQualified(rhs) || rhs.find('?') != std::string::npos) continue;
    const std::size_t use = readLine[name];
    if(use <= k || !canMove(rhs, k, use)) continue;
    std::string & target = lines[use];
    if(!isPlainStatement(target)) continue;
    // the one read of `name` (after the `=` of a declaration)
    std::string targetName, targetRhs;
    const std::string code = codeOf(target);
    const std::size_t from = parseDef(target, targetName, targetRhs) ? code.find(" = ") + 3 : 0;
    std::size_t at = std::string::npos;
    forEachLocal(code, [&](std::size_t i, std::size_t j) {
      if(i >= from && code.compare(i, j - i, name) == 0 && j - i == name.size()) at = i;
    });
    if(at == std::string::npos) continue;
    std::string candidate = target, value = rhs;
    std::size_t begin = at, end = at + name.size();
    const Left left = leftOf(candidate, begin);
    if(rhs[0] == '-' && kindOf(rhs) != Kind::Sum && (left == Left::Binary || left == Left::Unary) &&
       rightOf(candidate, end) != Right::Other)
    {
      // a + -x is a - x, a - -x is a + x, -(-x) is x: negation is exact, the sign moves to the operator
      std::size_t op = begin;
      while(candidate[op - 1] == ' ') --op;
      --op;
      value = rhs.substr(1);
      if(left == Left::Unary)
      {
        candidate.erase(op, 1);
        --begin;
        --end;
      }
      else candidate[op] = candidate[op] == '-' ? '+' : '-';
    }
    if(needsParentheses(value, candidate, begin, end)) value = "(" + value + ")";
    std::string replaced = candidate.substr(0, begin) + value + candidate.substr(end);
    if(longestLine(replaced) > maxLength) continue;
    target = std::move(replaced);
    removed[k] = true;
  }
  std::vector<std::string> out;
  for(std::size_t k = 0; k < n; ++k)
    if(!removed[k]) out.push_back(std::move(lines[k]));
  return out;
}

} // namespace rbdgen::cg
