#include "StaticStudy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "Pareto.h"

namespace rbdgen::accuracy
{

double scalarEpsilon(const std::string & scalar)
{
  if(scalar == "float") return std::numeric_limits<float>::epsilon();
  if(scalar == "double") return std::numeric_limits<double>::epsilon();
  throw std::runtime_error("unknown scalar '" + scalar + "'");
}

namespace
{

const std::map<std::string, std::string> & groupOf()
{
  static const std::map<std::string, std::string> g = {
      {"fk", "forward kinematics"},       {"id", "inverse dynamics"},   {"nle", "bias forces"},
      {"gravity", "gravity torques"},     {"mass_matrix", "mass matrix"}, {"fd_aba", "forward dynamics"},
      {"fd_crba", "forward dynamics"},      {"id_derivatives", "inverse dynamics derivatives"},
      {"fd_derivatives", "forward dynamics derivatives"},
  };
  return g;
}

ErrorStats compare(const VariantResult & v, const std::vector<Eigen::VectorXd> & ref)
{
  if(v.outputs.size() != ref.size()) throw std::runtime_error(v.function + ": wrong number of outputs");
  std::vector<double> e;
  for(std::size_t i = 0; i < ref.size(); ++i)
  {
    if(v.outputs[i].size() != ref[i].size())
      throw std::runtime_error(v.implementation + " " + v.function + ": output size " +
                               std::to_string(v.outputs[i].size()) + " instead of " + std::to_string(ref[i].size()));
    e.push_back(relativeError(v.outputs[i], ref[i]));
  }
  return summarize(e);
}

} // namespace

std::vector<StaticRow> evaluateStatic(const std::vector<VariantResult> & variants, const Reference & ref)
{
  const double condMax = ref.condH.empty() ? 1 : *std::max_element(ref.condH.begin(), ref.condH.end());
  std::vector<StaticRow> rows;
  for(const VariantResult & v : variants)
  {
    StaticRow r;
    r.group = groupOf().at(v.function);
    r.function = v.function;
    r.implementation = v.implementation;
    r.scalar = v.scalar;
    r.reference = v.function;
    r.label = v.implementation + " " + v.scalar + " " + v.function;
    r.nsPerCall = v.nsPerCall;
    r.error = compare(v, ref.outputs.at(v.function));
    const double eps = scalarEpsilon(v.scalar);
    const bool fd = v.function == "fd_aba" || v.function == "fd_crba";
    // d alphaD/dq = -H^-1 dID/dq(q, alpha, alphaD) applies H^-1 to a quantity that carries alphaD's error: cond^2
    const double grow = std::max(1.0, condMax / 1e3);
    r.bound = 1e4 * eps * (fd ? grow : v.function == "fd_derivatives" ? grow * grow : 1.0);
    rows.push_back(r);
    if(v.function == "gravity")
    {
      // The same outputs as bias forces: the error of leaving the velocity terms out.
      StaticRow b = r;
      b.group = "bias forces";
      b.reference = "nle";
      b.label = v.implementation + " " + v.scalar + " gravity (no velocity terms)";
      b.error = compare(v, ref.outputs.at("nle"));
      b.bound = std::numeric_limits<double>::infinity();
      rows.push_back(b);
    }
  }
  std::map<std::string, std::vector<std::size_t>> byGroup;
  for(std::size_t i = 0; i < rows.size(); ++i) byGroup[rows[i].group].push_back(i);
  for(const auto & [group, idx] : byGroup)
  {
    std::vector<CostError> pts;
    for(std::size_t i : idx) pts.push_back({rows[i].nsPerCall, rows[i].error.max});
    const std::vector<bool> front = paretoFront(pts);
    for(std::size_t k = 0; k < idx.size(); ++k) rows[idx[k]].pareto = front[k];
  }
  return rows;
}

} // namespace rbdgen::accuracy
