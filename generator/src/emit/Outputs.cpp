#include "Outputs.h"

#include <fmt/format.h>

namespace rbdgen::emit
{

namespace
{

std::string joined(std::initializer_list<const Vec3 *> vs)
{
  std::string s;
  for(const Vec3 * v : vs)
    for(int i = 0; i < 3; ++i) s += (s.empty() ? "" : ", ") + Block::text((*v)[i]);
  return s;
}

} // namespace

void writePose(Block & b, const std::string & dst, const Xform & X)
{
  Vec3 rows[3];
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) rows[r][c] = X.E(r, c);
  b.line(fmt::format("detail::set_pose({}, {});", dst, joined({&rows[0], &rows[1], &rows[2], &X.r})));
}

void writeMotion(Block & b, const std::string & dst, const Motion & m)
{
  b.line(fmt::format("detail::set_motion({}, {});", dst, joined({&m.w, &m.v})));
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
