// The gnuplot script of `rbdgen simulate`: three stacked panels read from the CSV by column name.
#include <sstream>

#include "Simulate.h"

namespace rbdgen::simulate
{

namespace
{

/// gnuplot string literal (single quotes; a quote is doubled).
std::string quoted(const std::string & s)
{
  std::string q = "'";
  for(char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

/// "plot 'f' using 1:N with lines title 'name', ..." for the given columns (1-based).
std::string plotColumns(const std::string & csv, const std::vector<std::string> & header,
                        const std::vector<std::size_t> & columns)
{
  std::ostringstream os;
  os << "plot ";
  for(std::size_t k = 0; k < columns.size(); ++k)
    os << (k ? ", \\\n     " : "") << (k ? "''" : quoted(csv)) << " using 1:" << columns[k] + 1
       << " with lines title " << quoted(header[columns[k]]);
  return os.str();
}

} // namespace

std::string gnuplotScript(const std::string & csv, const std::string & png, const std::vector<std::string> & header,
                          const std::string & title)
{
  std::vector<std::size_t> energy, joints, forces;
  for(std::size_t c = 1; c < header.size(); ++c)
  {
    const std::string & h = header[c];
    if(h == "kinetic" || h == "potential" || h == "contact_energy" || h == "total_energy") energy.push_back(c);
    else if(h.rfind("q_", 0) == 0 && h.rfind("q_Root", 0) != 0) joints.push_back(c);
    else if(h.rfind("fn_", 0) == 0) forces.push_back(c);
  }
  std::ostringstream os;
  os << "# written by rbdgen simulate; run: gnuplot <this file>\n"
     << "set terminal pngcairo size 1000,1200 noenhanced\n"
     << "set output " << quoted(png) << "\n"
     << "set datafile separator ','\n"
     << "set datafile columnheaders\n"
     << "set key outside right top\n"
     << "set grid\n"
     << "set multiplot layout 3,1 title " << quoted(title) << "\n"
     << "set title 'energy (J)'\n"
     << plotColumns(csv, header, energy) << "\n"
     << "set title 'joint positions (rad or m)'\n";
  if(joints.empty()) os << "set label 1 'no 1-dof joints' at graph 0.5, 0.5 center\nplot [0:1][0:1] 2 notitle\nunset label 1\n";
  else os << plotColumns(csv, header, joints) << "\n";
  os << "set title 'contact normal forces (N)'\nset xlabel 't (s)'\n";
  if(forces.empty()) os << "set label 1 'no contacts in this scene' at graph 0.5, 0.5 center\nplot [0:1][0:1] 2 notitle\n";
  else os << plotColumns(csv, header, forces) << "\n";
  os << "unset multiplot\n";
  return os.str();
}

} // namespace rbdgen::simulate
