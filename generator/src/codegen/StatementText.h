#pragma once
// Reading the emitted statements as text (the post-passes over a block's lines: InlineSingleUse,
// HomeInSlots): identifiers, the code of a line, `const S name = rhs;` definitions.

#include <algorithm>
#include <cctype>
#include <string>

namespace rbdgen::cg::text
{

inline bool isStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
inline bool isPart(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

/// The code of a line, without a trailing `// comment`.
inline std::string codeOf(const std::string & l)
{
  const auto p = l.find("//");
  return p == std::string::npos ? l : l.substr(0, p);
}

/// `const S name = rhs;` (at the block's top level: no indentation) -> name, rhs.
inline bool parseDef(const std::string & l, std::string & name, std::string & rhs)
{
  if(l.rfind("const S ", 0) != 0 || l.empty() || l.back() != ';') return false;
  const auto eq = l.find(" = ");
  if(eq == std::string::npos) return false;
  name = l.substr(8, eq - 8);
  rhs = l.substr(eq + 3, l.size() - eq - 4);
  return !name.empty() && std::all_of(name.begin(), name.end(), isPart);
}

/// Positions [i, j) of the names read as locals in `code` (not a member after `.`, not qualified
/// after `::`, not part of a longer name).
template<typename F>
void forEachLocal(const std::string & code, F && f)
{
  for(std::size_t i = 0; i < code.size();)
  {
    if(isStart(code[i]) && (i == 0 || !isPart(code[i - 1])))
    {
      std::size_t j = i;
      while(j < code.size() && isPart(code[j])) ++j;
      const bool member = i > 0 && (code[i - 1] == '.' || (i > 1 && code[i - 1] == ':' && code[i - 2] == ':'));
      if(!member) f(i, j);
      i = j;
    }
    else ++i;
  }
}

} // namespace rbdgen::cg::text
