// The generator's building blocks: template filling, identifiers, constant folding, dead-code
// removal, axis specialisation of joint kernels, SHA-256 (FIPS 180-4 test vectors).
#include <gtest/gtest.h>

#include "codegen/Expr.h"
#include "passes/JointKernels.h"
#include "emit/Template.h"
#include "model/RobotModel.h"
#include "util/Sha256.h"

namespace
{
using namespace rbdgen;
using rbdgen::cg::Block;
using rbdgen::cg::Scalar;
using rbdgen::cg::Term;

TEST(Template, FillsEveryPlaceholder)
{
  EXPECT_EQ(fillTemplate("a {{x}} b {{y}}{{x}}", {{"x", "1"}, {"y", "{{z}}"}}, "t"), "a 1 b {{z}}1");
}

TEST(Template, UnknownPlaceholderIsAnError)
{
  EXPECT_THROW(fillTemplate("a {{x}} {{nope}}", {{"x", "1"}}, "t"), TemplateError);
}

TEST(Template, UnusedValueIsAnError)
{
  EXPECT_THROW(fillTemplate("a {{x}}", {{"x", "1"}, {"extra", "2"}}, "t"), TemplateError);
}

TEST(Template, UnterminatedPlaceholderIsAnError)
{
  EXPECT_THROW(fillTemplate("a {{x", {{"x", "1"}}, "t"), TemplateError);
}

TEST(Template, SectionsKeepTheirLinesByFlagAndInvertedSectionsTheOpposite)
{
  const std::string t = "a\n{{#on}}\nb\n{{/on}}\n{{^on}}\nc\n{{/on}}\n{{#off}}\nd\n{{/off}}\n{{^off}}\ne\n{{/off}}\nf\n";
  EXPECT_EQ(selectSections(t, {{"on", true}, {"off", false}}, "t"), "a\nb\ne\nf\n");
  EXPECT_EQ(selectSections(t, {{"on", false}, {"off", true}}, "t"), "a\nc\nd\nf\n");
  EXPECT_THROW(selectSections("{{^x}}\na\n{{/y}}\n", {{"x", true}, {"y", true}}, "t"), TemplateError); // unbalanced
  EXPECT_THROW(selectSections("{{^x}}\na\n", {{"x", true}}, "t"), TemplateError);                     // not closed
}

TEST(Identifiers, AreValidCxx)
{
  EXPECT_EQ(sanitizeIdentifier("my-robot"), "my_robot");
  EXPECT_EQ(sanitizeIdentifier("2dof arm"), "_2dof_arm");
  EXPECT_EQ(sanitizeIdentifier("a__b"), "a_b");
  EXPECT_EQ(sanitizeIdentifier("_Foo"), "x_Foo");
  EXPECT_EQ(sanitizeIdentifier("int"), "int_");
  EXPECT_EQ(sanitizeIdentifier("link/1.2"), "link_1_2");
  EXPECT_EQ(sanitizeIdentifier(""), "_");
}

TEST(Folding, ConstantsFoldAndTrivialSumsEmitNothing)
{
  Block b;
  const Scalar x = Scalar::var("x"), y = Scalar::var("y");
  EXPECT_EQ(b.sum({Term{1.0, {x}}}, "t").name(), "x");                                   // x
  EXPECT_TRUE(b.sum({Term{0.0, {x}}, Term{2.0, {Scalar::constant(0.0), y}}}, "t").isZero()); // 0 x + 2 * 0 * y
  const Scalar c = b.sum({Term{2.0, {Scalar::constant(3.0)}}, Term{-1.0, {}}}, "t");       // 2 * 3 - 1
  ASSERT_TRUE(c.isConst());
  EXPECT_EQ(c.value(), 5.0);
  EXPECT_TRUE(b.lines().empty());
  const Scalar s = b.sum({Term{1.0, {x, Scalar::constant(1.0)}}, Term{-1.0, {y}}}, "s");
  ASSERT_EQ(b.lines().size(), 1u);
  EXPECT_EQ(b.lines()[0], "const S s = x - y;");
  EXPECT_EQ(b.mults(), 0);
  EXPECT_EQ(b.adds(), 1);
  EXPECT_FALSE(s.isConst());
}

TEST(Folding, UnusedLocalsAreRemoved)
{
  Block b;
  const Scalar x = Scalar::var("x");
  const Scalar used = b.sum({Term{2.0, {x}}}, "used");
  b.sum({Term{3.0, {x}}}, "unused");
  b.line("out = " + Block::text(used) + " * " + Block::text(used) + ";"); // (read twice: not inlined)
  const std::string text = b.str("");
  EXPECT_NE(text.find("const S used = S(2) * x;"), std::string::npos);
  EXPECT_EQ(text.find("unused"), std::string::npos);
}

TEST(Folding, LiteralsRoundTrip)
{
  for(double v : {0.1, 1.0 / 3.0, -2.5e-7, 9.81, 123456789.0})
  {
    const std::string t = Block::literal(v); // "S(...)"
    EXPECT_EQ(std::stod(t.substr(2, t.size() - 3)), v) << t;
  }
}

// A named constant (a model parameter) reads by name where it is used as it is, and folds like any
// other constant as soon as it is combined with another one; the values never change.
TEST(Folding, NamedConstantsAreReadByNameWhereUsedAsTheyAre)
{
  Block b;
  const Scalar x = Scalar::var("x"), y = Scalar::var("y");
  const Scalar r = Scalar::named(0.425, "model::j2.rz"), m = Scalar::named(2.5, "model::j2.m");
  EXPECT_EQ(Block::text(r), "S(model::j2.rz)");
  EXPECT_EQ(r.value(), 0.425);
  // 0 and +-1 are plain constants: they fold away
  EXPECT_TRUE(Scalar::named(1.0, "model::j0.E00").label().empty());
  EXPECT_TRUE(Scalar::named(0.0, "model::j0.rx").label().empty());
  EXPECT_EQ(Block::text(Scalar::named(-1.0, "model::j0.E01")), "S(-1)");
  // a factor of a product, with a sign or a factor of -1: by name
  b.sum({Term{1.0, {r, x}}}, "a");
  b.sum({Term{-1.0, {r, x}}, Term{1.0, {y}}}, "b");
  b.sum({Term{1.0, {Scalar::constant(-1.0), x, r}}}, "c");
  // combined with another constant: a literal of the product
  b.sum({Term{2.0, {r, x}}}, "d");
  b.sum({Term{1.0, {r, m, x}}}, "e");
  // a sum's lone constant: by name when one named constant is all of it
  b.sum({Term{1.0, {x}}, Term{1.0, {r}}}, "f");
  b.sum({Term{1.0, {x}}, Term{-1.0, {r}}}, "g");
  b.sum({Term{1.0, {x}}, Term{1.0, {r}}, Term{1.0, {m}}}, "h");
  ASSERT_EQ(b.lines().size(), 8u);
  EXPECT_EQ(b.lines()[0], "const S a = S(model::j2.rz) * x;");
  EXPECT_EQ(b.lines()[1], "const S b = -S(model::j2.rz) * x + y;");
  EXPECT_EQ(b.lines()[2], "const S c = -S(model::j2.rz) * x;");
  EXPECT_EQ(b.lines()[3], "const S d = S(0.85) * x;");
  EXPECT_EQ(b.lines()[4], "const S e = S(1.0625) * x;");
  EXPECT_EQ(b.lines()[5], "const S f = x + S(model::j2.rz);");
  EXPECT_EQ(b.lines()[6], "const S g = x - S(model::j2.rz);");
  EXPECT_EQ(b.lines()[7], "const S h = x + S(2.925);");
  // folded sums of constants keep the name only when it is the whole value
  const Scalar alone = b.sum({Term{1.0, {r}}}, "t"), negated = b.sum({Term{-1.0, {r}}}, "t");
  const Scalar folded = b.sum({Term{1.0, {r}}, Term{1.0, {Scalar::constant(0.5)}}}, "t");
  ASSERT_TRUE(alone.isConst() && negated.isConst() && folded.isConst());
  EXPECT_EQ(Block::text(alone), "S(model::j2.rz)");
  EXPECT_EQ(Block::text(negated), "S(-model::j2.rz)");
  EXPECT_EQ(negated.value(), -0.425);
  EXPECT_EQ(Block::text(folded), "S(0.925)");
  // a negated name read as a factor: the sign moves to the term, never a double negation
  b.sum({Term{1.0, {negated, y}}}, "i");
  b.sum({Term{-1.0, {negated, y}}}, "j");
  EXPECT_EQ(b.lines()[8], "const S i = -S(model::j2.rz) * y;");
  EXPECT_EQ(b.lines()[9], "const S j = S(model::j2.rz) * y;");
  // the operation counts are those of the literals
  Block lit;
  lit.sum({Term{1.0, {Scalar::constant(0.425), x}}}, "a");
  Block named;
  named.sum({Term{1.0, {r, x}}}, "a");
  EXPECT_EQ(lit.mults(), named.mults());
}

// A revolute joint about z touches only the xy block of its rotation: the other entries are the
// constants 0 and 1, so no operation is ever emitted for them.
TEST(Kernels, RevoluteAboutZIsSpecialised)
{
  MovingJoint mj;
  mj.joint = rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d::UnitZ(), true, "j");
  mj.nq = mj.nv = 1;
  mj.tag = "j0";
  Block b;
  const passes::JointKernel K = passes::emitJointKernel(b, mj, "q");
  for(int i = 0; i < 3; ++i)
  {
    EXPECT_TRUE(K.Xj.r[i].isZero());
    EXPECT_TRUE(K.Xj.E(2, i).isConst());
    EXPECT_TRUE(K.Xj.E(i, 2).isConst());
  }
  EXPECT_EQ(K.Xj.E(2, 2).value(), 1.0);
  EXPECT_FALSE(K.Xj.E(0, 0).isConst());
  EXPECT_EQ(b.calls(), 2); // one sin, one cos
  ASSERT_EQ(K.S.size(), 1u);
  EXPECT_EQ(K.S[0].w[2].value(), 1.0);
  EXPECT_TRUE(K.S[0].w[0].isZero() && K.S[0].v[0].isZero());
}

TEST(Kernels, GeneralAxisUsesEveryEntry)
{
  MovingJoint mj;
  mj.joint = rbd::Joint(rbd::Joint::Rev, Eigen::Vector3d(1, 2, 3), true, "j");
  mj.nq = mj.nv = 1;
  mj.tag = "j0";
  Block b;
  const passes::JointKernel K = passes::emitJointKernel(b, mj, "q");
  for(int r = 0; r < 3; ++r)
    for(int c = 0; c < 3; ++c) EXPECT_FALSE(K.Xj.E(r, c).isConst());
}

TEST(Sha256, FipsTestVectors)
{
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

} // namespace
