#include "HomeInSlots.h"

#include "StatementText.h"

#include <algorithm>
#include <map>

namespace rbdgen::cg
{

namespace
{

using text::codeOf;
using text::forEachLocal;
using text::isPart;
using text::parseDef;

/// `a[i][j] = x;` or `a(i, j) = x;` with a in arrays and x a name: slot "a[i][j]", its array, x.
bool parseCopy(const std::string & l, const std::set<std::string> & arrays, std::string & slot, std::string & array,
               std::string & name)
{
  std::size_t i = 0;
  while(i < l.size() && isPart(l[i])) ++i;
  array = l.substr(0, i);
  if(!arrays.count(array)) return false;
  const auto eq = l.find(" = ");
  if(eq == std::string::npos || l.back() != ';') return false;
  slot = l.substr(0, eq);
  const std::string index = slot.substr(i);
  const bool brackets = !index.empty() && index.front() == '[' && index.back() == ']';
  const bool parens = !index.empty() && index.front() == '(' && index.back() == ')';
  if(!brackets && !parens) return false;
  for(const char c : index)
    if(!(std::isdigit(static_cast<unsigned char>(c)) || c == '[' || c == ']' || c == '(' || c == ')' || c == ',' || c == ' '))
      return false;
  name = l.substr(eq + 3, l.size() - eq - 4);
  return !name.empty() && std::all_of(name.begin(), name.end(), isPart) && !std::isdigit(static_cast<unsigned char>(name[0]));
}

/// The arrays of `arrays` a top-level line declares (`S a[n][m];`, `S a[n][m], b[n][m];`,
/// `Eigen::Matrix<S, r, c> a;`).
std::vector<std::string> declaredArrays(const std::string & l, const std::set<std::string> & arrays)
{
  std::vector<std::string> out;
  if(l.empty() || l.back() != ';') return out;
  if(l.rfind("Eigen::Matrix<S, ", 0) == 0)
  {
    const auto space = l.rfind(' ');
    const std::string a = l.substr(space + 1, l.size() - space - 2);
    if(arrays.count(a)) out.push_back(a);
    return out;
  }
  if(l.rfind("S ", 0) != 0) return out;
  // declarators `name[n]...` separated by ", "
  for(std::size_t i = 2; i < l.size();)
  {
    std::size_t j = i;
    while(j < l.size() && isPart(l[j])) ++j;
    if(j == i || j == l.size() || l[j] != '[') return {};
    if(arrays.count(l.substr(i, j - i))) out.push_back(l.substr(i, j - i));
    while(j < l.size() && l[j] != ',' && l[j] != ';') ++j;
    i = j + 2;
  }
  return out;
}

/// l with every name of `home` read as a local (from position `from` on) replaced by its slot.
std::string readSlots(const std::string & l, const std::map<std::string, std::string> & home, std::size_t from = 0)
{
  std::string out = l.substr(0, from);
  std::size_t last = from;
  const std::string code = codeOf(l);
  forEachLocal(code, [&](std::size_t i, std::size_t j) {
    if(i < from) return;
    const auto h = home.find(code.substr(i, j - i));
    if(h == home.end()) return;
    out += l.substr(last, i - last) + h->second;
    last = j;
  });
  return out + l.substr(last);
}

/// l with every slot of `alias` (`a[i][j]`, `a(i, j)`, not part of a longer name) replaced by the
/// slot it stands for.
std::string readAliases(const std::string & l, const std::map<std::string, std::string> & alias)
{
  if(alias.empty()) return l;
  std::string out;
  std::size_t last = 0;
  const std::string code = codeOf(l);
  forEachLocal(code, [&](std::size_t i, std::size_t j) {
    if(i < last) return;
    std::size_t e = j;
    if(e < code.size() && code[e] == '(') e = code.find(')', e);
    else
      while(e < code.size() && code[e] == '[')
      {
        const std::size_t close = code.find(']', e);
        if(close == std::string::npos) break;
        e = close + 1;
        if(e >= code.size() || code[e] != '[') --e;
      }
    if(e == std::string::npos || e == j) return;
    const auto a = alias.find(code.substr(i, e + 1 - i));
    if(a == alias.end()) return;
    out += l.substr(last, i - last) + a->second;
    last = e + 1;
  });
  return out + l.substr(last);
}

} // namespace

std::vector<std::string> homeInSlots(const std::vector<std::string> & lines, const std::set<std::string> & arrays,
                                     const std::set<std::string> & readByElement, const std::set<std::string> & changedInPlace)
{
  const std::size_t n = lines.size();
  // top level: outside every brace (lambda bodies, loops)
  std::vector<bool> top(n);
  int depth = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    top[k] = depth == 0;
    for(const char c : codeOf(lines[k])) depth += c == '{' ? 1 : (c == '}' ? -1 : 0);
  }
  std::map<std::string, std::size_t> defLine;
  std::map<std::string, int> writes; // assignments per slot, anywhere
  for(std::size_t k = 0; k < n; ++k)
  {
    std::string name, rhs;
    if(top[k] && parseDef(lines[k], name, rhs)) defLine.emplace(name, k);
    std::size_t i = lines[k].find_first_not_of(' ');
    if(i == std::string::npos) continue;
    const std::string l = lines[k].substr(i);
    const auto eq = l.find(" = ");
    if(eq != std::string::npos) ++writes[l.substr(0, eq)];
  }
  // arrays changed in place: the lines that name them other than by a copy or an assignment to a
  // slot (their first after a copy bounds the reads of the value copied), and each name's last read
  std::map<std::string, std::vector<std::size_t>> changes;
  std::map<std::string, std::size_t> lastRead;
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::string code = codeOf(lines[k]);
    std::string name, rhs, slot, array, copied;
    const bool def = parseDef(lines[k], name, rhs);
    const bool copy = parseCopy(lines[k], arrays, slot, array, copied);
    forEachLocal(code, [&](std::size_t i, std::size_t j) {
      const std::string id = code.substr(i, j - i);
      // (a plain assignment to one of its slots, `a[i] = e;`, is not a change: counted in writes)
      const bool assignment = i == 0 && code.compare(j, 1, "[") == 0 && code.find(" = ") != std::string::npos;
      if(changedInPlace.count(id) && !copy && !assignment && (changes[id].empty() || changes[id].back() != k))
        changes[id].push_back(k);
      if(!(def && i < name.size() + 8 && id == name)) lastRead[id] = k;
    });
  }
  const auto changedBefore = [&](const std::string & array, std::size_t copy, std::size_t read) {
    const auto c = changes.find(array);
    if(c == changes.end()) return false;
    const auto after = std::upper_bound(c->second.begin(), c->second.end(), copy);
    return after != c->second.end() && *after <= read;
  };
  // the first copy of each defined name into a slot written once: its home
  std::map<std::string, std::string> home;
  std::map<std::string, std::string> homeArray;
  std::vector<bool> dropped(n, false);
  for(std::size_t k = 0; k < n; ++k)
  {
    std::string slot, array, name;
    if(!top[k] || !parseCopy(lines[k], arrays, slot, array, name)) continue;
    const auto d = defLine.find(name);
    if(d == defLine.end() || d->second > k || home.count(name) || writes[slot] != 1) continue;
    if(changedBefore(array, k, lastRead[name])) continue;
    home[name] = slot;
    homeArray[name] = array;
    dropped[k] = true;
  }
  if(home.empty()) return lines;
  // further copies of a homed value into an array read by element only: its reads read the home
  std::map<std::string, std::string> alias;
  for(std::size_t k = 0; k < n; ++k)
  {
    std::string slot, array, name;
    if(dropped[k] || !top[k] || !parseCopy(lines[k], arrays, slot, array, name) || !readByElement.count(array)) continue;
    const auto h = home.find(name);
    if(h == home.end() || writes[slot] != 1 || defLine[name] > k) continue;
    alias[slot] = h->second;
    dropped[k] = true;
  }
  // declarations move up to the first home in the arrays they declare
  std::map<std::string, std::size_t> declLine, firstHome;
  for(std::size_t k = 0; k < n; ++k)
    if(top[k])
      for(const std::string & a : declaredArrays(lines[k], arrays))
        if(!declLine.count(a)) declLine[a] = k;
  for(const auto & [name, array] : homeArray)
  {
    const std::size_t k = defLine[name];
    if(!firstHome.count(array) || k < firstHome[array]) firstHome[array] = k;
  }
  std::map<std::size_t, std::size_t> moveTo; // declaration line -> the line it moves before
  for(const auto & [array, k] : firstHome)
  {
    const auto d = declLine.find(array);
    if(d == declLine.end() || d->second < k) continue;
    const auto m = moveTo.find(d->second);
    moveTo[d->second] = m == moveTo.end() ? k : std::min(m->second, k);
  }
  std::map<std::size_t, std::vector<std::string>> before; // line -> declarations moved before it
  for(const auto & [decl, k] : moveTo)
  {
    before[k].push_back(lines[decl]);
    dropped[decl] = true;
  }
  std::vector<std::string> out;
  out.reserve(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    if(const auto b = before.find(k); b != before.end())
      for(const std::string & l : b->second) out.push_back(l);
    if(dropped[k]) continue;
    std::string name, rhs;
    if(top[k] && parseDef(lines[k], name, rhs) && home.count(name) && defLine[name] == k)
    {
      const std::string l = home[name] + " = " + rhs + ";";
      out.push_back(readAliases(readSlots(l, home, home[name].size() + 3), alias));
      continue;
    }
    out.push_back(readAliases(readSlots(lines[k], home), alias));
  }
  return out;
}

} // namespace rbdgen::cg
