#include "Outputs.h"

#include <fmt/format.h>

namespace rbdgen::emit
{

void writePose(Block & b, const std::string & dst, const Xform & X)
{
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) b.line(fmt::format("{}.rotation({}, {}) = {};", dst, r, c, Block::text(X.E(r, c))));
  for(int i = 0; i < 3; ++i) b.line(fmt::format("{}.translation({}) = {};", dst, i, Block::text(X.r[i])));
}

void writeMotion(Block & b, const std::string & dst, const Motion & m)
{
  for(int i = 0; i < 3; ++i)
  {
    b.line(fmt::format("{}[{}] = {};", dst, i, Block::text(m.w[i])));
    b.line(fmt::format("{}[{}] = {};", dst, i + 3, Block::text(m.v[i])));
  }
}

void writeColumn(Block & b, const std::string & dst, int col, const Vec3 & top, const Vec3 & bottom)
{
  for(int r = 0; r < 3; ++r)
  {
    if(!top[r].isZero()) b.line(fmt::format("{}({}, {}) = {};", dst, r, col, Block::text(top[r])));
    if(!bottom[r].isZero()) b.line(fmt::format("{}({}, {}) = {};", dst, r + 3, col, Block::text(bottom[r])));
  }
}

std::string linkSlot(const RobotModel & rm, const std::string & dst, int body)
{
  return fmt::format("{}[detail::at(Body::{})]", dst, rm.bodies[static_cast<std::size_t>(body)].ident);
}

Xform kinFrame(int k)
{
  Xform X;
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) X.E(r, c) = Scalar::var(fmt::format("kin.frame[{}].rotation({}, {})", k, r, c));
  for(int i = 0; i < 3; ++i) X.r[i] = Scalar::var(fmt::format("kin.frame[{}].translation({})", k, i));
  return X;
}

Vec3 vec3Var(const std::string & name, int offset)
{
  Vec3 v;
  for(int c = 0; c < 3; ++c) v[c] = Scalar::var(fmt::format("{}({})", name, c + offset));
  return v;
}

} // namespace rbdgen::emit
