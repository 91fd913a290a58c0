#include "Report.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "ErrorStats.h"

namespace rbdgen::accuracy
{

namespace
{

std::string sci(double x)
{
  if(std::isnan(x)) return "n/a";
  if(std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("{:.2e}", x);
}

/// Numbers for CSV and gnuplot data: full precision, "nan"/"inf" spelled out.
std::string num(double x)
{
  if(std::isnan(x)) return "nan";
  if(std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return fmt::format("{:.6g}", x);
}

/// Short label of a static row for the plot: "gen float ABA".
std::string plotLabel(const StaticRow & r)
{
  std::string s = (r.implementation == "generated" ? "gen " : "rt ") + r.scalar;
  if(r.function == "fd_aba") s += " ABA";
  if(r.function == "fd_crba") s += " CRBA";
  if(r.group == "bias forces") s += r.function == "gravity" ? " no-vel" : " full";
  return s;
}

const std::vector<std::string> & groupOrder()
{
  static const std::vector<std::string> g = {"forward kinematics", "inverse dynamics", "bias forces",
                                             "gravity torques", "mass matrix", "forward dynamics",
                                             "inverse dynamics derivatives", "forward dynamics derivatives"};
  return g;
}

std::vector<const StaticRow *> rowsOf(const StudyResults & r, const std::string & group)
{
  std::vector<const StaticRow *> v;
  for(const StaticRow & row : r.staticRows)
    if(row.group == group) v.push_back(&row);
  return v;
}

std::string markdown(const StudyResults & r)
{
  const StudyInfo & i = r.info;
  std::string s;
  s += fmt::format("# Accuracy and speed: {}\n\n", i.robot);
  s += fmt::format("`rbdgen accuracy {}{}`: nq = {}, nv = {}, {} seeded random states (seed {}), "
                   "cond(H) median {:.1e}, max {:.1e}.\n\n",
                   i.urdf, i.options, i.nq, i.nv, i.states, i.seed, i.condHMedian, i.condHMax);
  s += "Reference: the runtime in `long double` on the same states. Error of one call: "
       "`||x - ref||_inf / max(1, ||ref||_inf)`; digits = -log10(error). Time per call: median of 7 runs over "
       "the pool (a different state each call). Generated code: compiled by `" +
       i.compiler +
       "`; runtime: rbdgen's own build, time per call includes setting the configuration, forward kinematics "
       "and forward velocity. Bound: the stated bound on the max error (1e4 eps, forward dynamics "
       "1e4 eps max(1, cond(H)/1e3), its derivatives the square of that factor); derivatives: [dtau/dq dtau/dalpha] and "
       "[dalphaD/dq dalphaD/dalpha Minv] side by side, q in the tangent space; `*` marks the Pareto front (time, max error) of each group.\n\n";
  for(const std::string & g : groupOrder())
  {
    const auto rows = rowsOf(r, g);
    if(rows.empty()) continue;
    s += fmt::format("## {}\n\n", g);
    s += "| variant | ns/call | max error | median error | digits (max) | bound | within | front |\n";
    s += "|---|---:|---:|---:|---:|---:|:---:|:---:|\n";
    for(const StaticRow * row : rows)
    {
      const bool bounded = std::isfinite(row->bound);
      s += fmt::format("| {} | {:.0f} | {} | {} | {:.1f} | {} | {} | {} |\n", row->label, row->nsPerCall,
                       sci(row->error.max), sci(row->error.median), digits(row->error.max),
                       bounded ? sci(row->bound) : "-", bounded ? (row->error.max <= row->bound ? "yes" : "NO") : "-",
                       row->pareto ? "*" : "");
    }
    s += "\n";
  }
  s += "![error vs time per call](accuracy_static.png)\n\n";
  if(r.simulation)
  {
    const SimulationStudy & sim = *r.simulation;
    s += "## Simulation: integrator x step size\n\n";
    s += fmt::format("Runtime scene dynamics in double, {}. Reference: the same scene in long double, RK4 "
                     "with dt = {:.1e} (its own error, estimated against dt x 2: {}; its energy drift {} J; "
                     "initial energy {:.6g} J). Trajectory error = relative error of q after the horizon; "
                     "energy error = max |E(t) - E_ref(t)| over the samples (J); order = observed order "
                     "of convergence against the previous step.\n\n",
                     sim.initialStateNote, sim.referenceDt, sci(sim.referenceError), sci(sim.referenceEnergyDrift),
                     sim.initialEnergy);
    s += "| integrator | dt (s) | wall s / sim s | q error | alpha error | energy error (J) | order | front |\n";
    s += "|---|---:|---:|---:|---:|---:|---:|:---:|\n";
    for(const SimulationRow & row : sim.rows)
      s += fmt::format("| {} | {:.0e} | {} | {} | {} | {} | {} | {} |\n", row.integrator, row.dt,
                       sci(row.wallPerSimSecond), row.diverged ? "diverged" : sci(row.trajectoryError),
                       row.diverged ? "-" : sci(row.velocityError), row.diverged ? "-" : sci(row.energyError),
                       std::isnan(row.observedOrder) ? "-" : fmt::format("{:.2f}", row.observedOrder),
                       row.pareto ? "*" : "");
    s += "\n![integrator error vs wall time](accuracy_simulation.png)\n";
  }
  return s;
}

std::string csv(const StudyResults & r)
{
  std::string s = "study,group,variant,function,implementation,scalar,reference,integrator,dt,ns_per_call,"
                  "wall_s_per_sim_s,max_error,median_error,digits_max,digits_median,bound,within_bound,"
                  "velocity_error,energy_error,observed_order,pareto\n";
  for(const StaticRow & row : r.staticRows)
  {
    const bool bounded = std::isfinite(row.bound);
    s += fmt::format("static,{},{},{},{},{},{},,,{},,{},{},{},{},{},{},,,,{}\n", row.group, row.label, row.function,
                     row.implementation, row.scalar, row.reference, num(row.nsPerCall), num(row.error.max),
                     num(row.error.median), num(digits(row.error.max)), num(digits(row.error.median)),
                     bounded ? num(row.bound) : "", bounded ? (row.error.max <= row.bound ? "1" : "0") : "",
                     row.pareto ? 1 : 0);
  }
  if(r.simulation)
    for(const SimulationRow & row : r.simulation->rows)
      s += fmt::format("simulation,integrator,{} dt={},,runtime,double,long double rk4,{},{},,{},{},,{},,,,{},{},{},{}\n",
                       row.integrator, num(row.dt), row.integrator, num(row.dt), num(row.wallPerSimSecond),
                       num(row.trajectoryError), num(digits(row.trajectoryError)), num(row.velocityError),
                       num(row.energyError), num(row.observedOrder), row.pareto ? 1 : 0);
  return s;
}

/// Data blocks per group (gnuplot `index`): 2k = every variant (ns, max error, "label"),
/// 2k+1 = its Pareto front sorted by time.
std::string staticData(const StudyResults & r, std::vector<std::string> & groups)
{
  std::string s;
  for(const std::string & g : groupOrder())
  {
    auto rows = rowsOf(r, g);
    if(rows.empty()) continue;
    groups.push_back(g);
    // Labels alternate above and below their point (4th column: factor on the label's y).
    std::sort(rows.begin(), rows.end(), [](const StaticRow * a, const StaticRow * b) { return a->nsPerCall < b->nsPerCall; });
    s += fmt::format("# {}: ns_per_call max_error label label_y_factor\n", g);
    for(std::size_t k = 0; k < rows.size(); ++k)
      s += fmt::format("{} {} \"{}\" {}\n", num(rows[k]->nsPerCall), num(std::max(rows[k]->error.max, 1e-20)),
                       plotLabel(*rows[k]), k % 2 ? "0.15" : "6");
    s += "\n\n";
    s += fmt::format("# {}: Pareto front\n", g);
    for(const StaticRow * row : rows)
      if(row->pareto) s += fmt::format("{} {}\n", num(row->nsPerCall), num(std::max(row->error.max, 1e-20)));
    s += "\n\n";
  }
  return s;
}

std::string staticScript(const StudyResults & r, const std::vector<std::string> & groups)
{
  std::string s = "# gnuplot accuracy_static.gp (in this directory): accuracy_static.png from accuracy_static.dat\n";
  s += "set terminal pngcairo size 1500,950 font 'sans,10'\nset output 'accuracy_static.png'\n";
  s += "set logscale xy\nset format y '10^{%L}'\nset grid\nset key off\nset offsets graph 0.1, graph 0.3, graph 0.1, graph 0.1\n";
  s += fmt::format("set multiplot layout 2,3 title \"{}: max error vs time per call (long double reference; "
                   "line: Pareto front)\"\n",
                   r.info.robot);
  for(std::size_t k = 0; k < groups.size(); ++k)
  {
    s += fmt::format("set title '{}'\nset xlabel 'ns per call'\nset ylabel 'max relative error'\n", groups[k]);
    s += fmt::format("plot 'accuracy_static.dat' index {} using 1:2 with points pt 7 ps 1.2 lc rgb '#1f77b4', "
                     "'' index {} using 1:($2*$4):3 with labels font 'sans,8', "
                     "'' index {} using 1:2 with linespoints lw 2 pt 6 ps 2 lc rgb '#d62728'\n",
                     2 * k, 2 * k, 2 * k + 1);
  }
  s += "unset multiplot\n";
  return s;
}

std::string simulationData(const SimulationStudy & sim, std::vector<std::string> & integrators)
{
  std::string s;
  for(const SimulationRow & row : sim.rows)
    if(std::find(integrators.begin(), integrators.end(), row.integrator) == integrators.end())
      integrators.push_back(row.integrator);
  for(const std::string & in : integrators)
  {
    s += fmt::format("# {}: wall_s_per_sim_s q_error \"dt\"\n", in);
    for(const SimulationRow & row : sim.rows)
      if(row.integrator == in && !row.diverged && std::isfinite(row.trajectoryError))
        s += fmt::format("{} {} \"{:.0e}\"\n", num(row.wallPerSimSecond), num(std::max(row.trajectoryError, 1e-20)), row.dt);
    s += "\n\n";
  }
  std::vector<const SimulationRow *> front;
  for(const SimulationRow & row : sim.rows)
    if(row.pareto) front.push_back(&row);
  std::sort(front.begin(), front.end(),
            [](const SimulationRow * a, const SimulationRow * b) { return a->wallPerSimSecond < b->wallPerSimSecond; });
  s += "# Pareto front\n";
  for(const SimulationRow * row : front) s += fmt::format("{} {}\n", num(row->wallPerSimSecond), num(row->trajectoryError));
  s += "\n\n";
  return s;
}

std::string simulationScript(const StudyResults & r, const std::vector<std::string> & integrators)
{
  std::string s = "# gnuplot accuracy_simulation.gp (in this directory): accuracy_simulation.png\n";
  s += "set terminal pngcairo size 1000,700 font 'sans,10'\nset output 'accuracy_simulation.png'\n";
  s += "set logscale xy\nset format y '10^{%L}'\nset grid\nset key top right\n";
  s += fmt::format("set title \"{}: trajectory error after {:g} s vs wall time (labels: dt; black: Pareto front)\"\n",
                   r.info.robot, r.simulation ? r.simulation->horizon : 0.0);
  s += "set xlabel 'wall time per simulated second (s)'\nset ylabel 'relative error of q(T)'\n";
  s += "plot ";
  for(std::size_t k = 0; k < integrators.size(); ++k)
    s += fmt::format("'accuracy_simulation.dat' index {} using 1:2 with linespoints lw 2 pt 7 title '{}' noenhanced, "
                     "'' index {} using 1:2:3 with labels offset char 0,1 font 'sans,8' notitle, ",
                     k, integrators[k], k);
  s += fmt::format("'' index {} using 1:2 with lines lw 1 dt 2 lc rgb 'black' title 'Pareto front'\n", integrators.size());
  return s;
}

} // namespace

std::map<std::string, std::string> renderReport(const StudyResults & r)
{
  std::map<std::string, std::string> files;
  files["accuracy.md"] = markdown(r);
  files["accuracy.csv"] = csv(r);
  std::vector<std::string> groups;
  files["accuracy_static.dat"] = staticData(r, groups);
  files["accuracy_static.gp"] = staticScript(r, groups);
  if(r.simulation)
  {
    std::vector<std::string> integrators;
    files["accuracy_simulation.dat"] = simulationData(*r.simulation, integrators);
    files["accuracy_simulation.gp"] = simulationScript(r, integrators);
  }
  return files;
}

std::vector<std::string> plotImages(const StudyResults & r)
{
  std::vector<std::string> v = {"accuracy_static.png"};
  if(r.simulation) v.push_back("accuracy_simulation.png");
  return v;
}

} // namespace rbdgen::accuracy
