#include "States.h"

#include <fstream>
#include <random>
#include <stdexcept>

namespace rbdgen::accuracy
{

std::vector<State> randomStates(const rbd::MultiBody & mb, int count, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  std::normal_distribution<double> gauss(0, 1);
  std::vector<State> states;
  for(int s = 0; s < count; ++s)
  {
    State st{Eigen::VectorXd(mb.nrParams()), Eigen::VectorXd(mb.nrDof()), Eigen::VectorXd(mb.nrDof()),
             Eigen::VectorXd(mb.nrDof())};
    for(int i = 0; i < mb.nrJoints(); ++i)
    {
      const auto & j = mb.joint(i);
      const int p = mb.jointPosInParam(i);
      for(int k = 0; k < j.params(); ++k) st.q(p + k) = 3 * u(rng);
      if(j.type() == rbd::JointType::Spherical || j.type() == rbd::JointType::Free)
      {
        // A normalised 4-d Gaussian is uniform on the unit sphere of quaternions.
        // (one draw per statement: argument evaluation order is unspecified, seeds must not depend on the compiler)
        Eigen::Vector4d quat;
        for(int k = 0; k < 4; ++k) quat[k] = gauss(rng);
        st.q.segment<4>(p) = quat.normalized();
      }
    }
    for(int k = 0; k < mb.nrDof(); ++k)
    {
      st.alpha(k) = 2 * u(rng);
      st.alphaD(k) = 2 * u(rng);
      st.tau(k) = 2 * u(rng);
    }
    states.push_back(std::move(st));
  }
  return states;
}

void writeStates(const std::string & path, const std::vector<State> & states, int nq, int nv)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if(!out) throw std::runtime_error(path + ": cannot write the states file");
  const std::int32_t header[3] = {static_cast<std::int32_t>(states.size()), nq, nv};
  out.write(reinterpret_cast<const char *>(header), sizeof(header));
  for(const State & s : states)
    for(const Eigen::VectorXd * v : {&s.q, &s.alpha, &s.alphaD, &s.tau})
      out.write(reinterpret_cast<const char *>(v->data()), static_cast<std::streamsize>(v->size() * sizeof(double)));
  if(!out) throw std::runtime_error(path + ": cannot write the states file");
}

} // namespace rbdgen::accuracy
