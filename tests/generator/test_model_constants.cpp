// The generated header's named model constants (ur5e::model::j<k>.E01, .ry, .m, .hz, .I22...) against
// the URDF text, read here
// with tinyxml2 and converted by the formulas the header documents, independently of the loader:
//   X_T = (E, r): r = the joint origin's xyz, E = R(rpy)^T with R = Rz(yaw) Ry(pitch) Rx(roll),
//                 entries within 1e-14 of 0 or +-1 snapped (docs/DESIGN.md: URDF round-off);
//   m = the child link's mass, h = m c (c: the inertial origin), I = R_i I_c R_i^T + m (c.c 1 - c c^T)
//   (the rotational inertia at the link origin, R_i from the inertial rpy).
// ur5e attaches no massive link by a fixed joint, so each joint's body is its child link alone.
#include <ur5e/dynamics.hpp>

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <Eigen/Geometry>

#include <cmath>
#include <sstream>
#include <string>

namespace
{

Eigen::Vector3d triple(const tinyxml2::XMLElement * e, const char * attribute)
{
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  if(e && e->Attribute(attribute))
  {
    std::istringstream in(e->Attribute(attribute));
    in >> v.x() >> v.y() >> v.z();
  }
  return v;
}

Eigen::Matrix3d rotationRpy(const Eigen::Vector3d & rpy)
{
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

double snapped(double x)
{
  for(double target : {-1.0, 0.0, 1.0})
    if(std::abs(x - target) <= 1e-14) return target;
  return x;
}

// The members by index: E(a, b) = E<a><b>, r(a) = r<x|y|z>, h(a) = h<x|y|z>, I(a, b) = I<a><b>.
using L = ur5e::LinkConstants;
using J = ur5e::JointConstants;
constexpr double L::*kE[3][3] = {{&L::E00, &L::E01, &L::E02}, {&L::E10, &L::E11, &L::E12}, {&L::E20, &L::E21, &L::E22}};
constexpr double L::*kR[3] = {&L::rx, &L::ry, &L::rz};
constexpr double J::*kH[3] = {&J::hx, &J::hy, &J::hz};
constexpr double J::*kI[3][3] = {{&J::I00, &J::I01, &J::I02}, {&J::I10, &J::I11, &J::I12}, {&J::I20, &J::I21, &J::I22}};

const tinyxml2::XMLElement * link(const tinyxml2::XMLDocument & doc, const std::string & name)
{
  for(auto * l = doc.RootElement()->FirstChildElement("link"); l; l = l->NextSiblingElement("link"))
    if(name == l->Attribute("name")) return l;
  return nullptr;
}

TEST(ModelConstants, AreTheUrdfValues)
{
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.LoadFile(RBDGEN_UR5E_URDF), tinyxml2::XML_SUCCESS);
  const ur5e::JointConstants * constants[] = {&ur5e::model::j0, &ur5e::model::j1, &ur5e::model::j2,
                                              &ur5e::model::j3, &ur5e::model::j4, &ur5e::model::j5};
  static_assert(ur5e::nv == 6, "one constant per revolute joint of ur5e");
  int k = 0;
  for(auto * j = doc.RootElement()->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint"))
  {
    if(std::string(j->Attribute("type")) == "fixed") continue;
    ASSERT_LT(k, 6);
    ASSERT_EQ(std::string(ur5e::dof_names[static_cast<std::size_t>(k)]), j->Attribute("name"));
    const ur5e::JointConstants & c = *constants[k++];
    SCOPED_TRACE(j->Attribute("name"));
    // X_T
    const auto * origin = j->FirstChildElement("origin");
    const Eigen::Vector3d r = triple(origin, "xyz");
    const Eigen::Matrix3d E = rotationRpy(triple(origin, "rpy")).transpose();
    for(int a = 0; a < 3; ++a)
    {
      EXPECT_EQ(c.*kR[a], r[a]);
      for(int b = 0; b < 3; ++b) EXPECT_NEAR(c.*kE[a][b], snapped(E(a, b)), 1e-16) << a << b;
    }
    // the child link's inertia at its origin
    const auto * inertial = link(doc, j->FirstChildElement("child")->Attribute("link"))->FirstChildElement("inertial");
    ASSERT_NE(inertial, nullptr);
    const double m = inertial->FirstChildElement("mass")->DoubleAttribute("value");
    const Eigen::Vector3d com = triple(inertial->FirstChildElement("origin"), "xyz");
    const auto * in = inertial->FirstChildElement("inertia");
    Eigen::Matrix3d Ic;
    Ic << in->DoubleAttribute("ixx"), in->DoubleAttribute("ixy"), in->DoubleAttribute("ixz"), in->DoubleAttribute("ixy"),
        in->DoubleAttribute("iyy"), in->DoubleAttribute("iyz"), in->DoubleAttribute("ixz"), in->DoubleAttribute("iyz"),
        in->DoubleAttribute("izz");
    const Eigen::Matrix3d Ri = rotationRpy(triple(inertial->FirstChildElement("origin"), "rpy"));
    const Eigen::Matrix3d I = Ri * Ic * Ri.transpose() + m * (com.dot(com) * Eigen::Matrix3d::Identity() - com * com.transpose());
    EXPECT_EQ(c.m, m);
    for(int a = 0; a < 3; ++a)
    {
      EXPECT_NEAR(c.*kH[a], m * com[a], 1e-15 * m);
      for(int b = 0; b < 3; ++b)
      {
        EXPECT_NEAR(c.*kI[a][b], I(a, b), 1e-15 * I.norm()) << a << b;
        EXPECT_EQ(c.*kI[a][b], c.*kI[b][a]);
      }
    }
  }
  EXPECT_EQ(k, 6);
}

// The names are what the code reads: the header's functions use them where the literals were (the
// generated-vs-runtime suite checks the values the functions compute).
TEST(ModelConstants, AreConstantExpressions)
{
  constexpr double lift = ur5e::model::j2.rx + ur5e::model::j1.m;
  static_assert(lift != 0.0, "usable in constant expressions");
  EXPECT_EQ(lift, ur5e::model::j2.rx + ur5e::model::j1.m);
}

} // namespace
