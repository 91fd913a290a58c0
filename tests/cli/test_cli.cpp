// rbdgen CLI: --help/--version, usage errors, provenance of the generated header, determinism,
// write-if-changed, `rbdgen info`. Expected values come from the URDF text, CMakeLists.txt
// (version) and coreutils' sha256sum, never from rbdgen itself.
#include <regex>
#include <set>

#include "CliRun.h"

namespace clitest
{
namespace
{

/// project(rbdgen VERSION x.y.z) of the top-level CMakeLists.txt.
std::string projectVersion()
{
  const std::string text = readFile(fs::path(RBDGEN_SOURCE_DIR) / "CMakeLists.txt");
  std::smatch m;
  if(!std::regex_search(text, m, std::regex(R"re(project\(rbdgen\s+VERSION\s+([0-9.]+))re"))) return "?";
  return m[1];
}

/// Every match of group 1 of `re` in text.
std::vector<std::string> allMatches(const std::string & text, const std::string & re)
{
  std::vector<std::string> v;
  const std::regex r(re);
  for(auto it = std::sregex_iterator(text.begin(), text.end(), r); it != std::sregex_iterator(); ++it)
    v.push_back((*it)[1]);
  return v;
}

std::vector<std::string> lines(const std::string & text)
{
  std::vector<std::string> v;
  std::size_t b = 0;
  for(std::size_t e; (e = text.find('\n', b)) != std::string::npos; b = e + 1) v.push_back(text.substr(b, e - b));
  if(b < text.size()) v.push_back(text.substr(b));
  return v;
}

// ---------------------------------------------------------------------------------------------
// --help, --version, usage errors

TEST_F(CliTest, HelpExitsZeroAndListsSubcommands)
{
  const Result r = rbdgen({"--help"}, dir());
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.err, "");
  for(const char * word : {"Usage", "generate", "info", "--version"}) EXPECT_NE(r.out.find(word), std::string::npos) << word;

  const Result g = rbdgen({"generate", "--help"}, dir());
  EXPECT_EQ(g.code, 0);
  for(const char * word : {"--out", "--namespace", "--floating-base", "--base-link"})
    EXPECT_NE(g.out.find(word), std::string::npos) << word;
  EXPECT_TRUE(listTree(dir()).empty());
}

TEST_F(CliTest, VersionExitsZeroAndMatchesTheProject)
{
  const Result r = rbdgen({"--version"}, dir());
  EXPECT_EQ(r.code, 0);
  EXPECT_EQ(r.out, "rbdgen " + projectVersion() + "\n");
  EXPECT_EQ(r.err, "");
}

TEST_F(CliTest, UsageErrorsAreOneLine)
{
  const std::string ur5e = robot("ur5e").string();
  const std::vector<std::vector<std::string>> cases = {
      {},                                            // no subcommand
      {"--bogus"},                                   // unknown option
      {"compile", ur5e},                             // unknown subcommand
      {"generate"},                                  // missing URDF
      {"generate", ur5e},                            // missing --out
      {"generate", ur5e, "--out"},                   // --out without its value
      {"generate", ur5e, "--out", "o", "--bogus"},   // unknown option of the subcommand
      {"info"},                                      // missing URDF
      {"info", ur5e, "extra.urdf"},                  // one URDF only
  };
  for(const auto & args : cases)
  {
    std::string shown;
    for(const auto & a : args) shown += a + " ";
    const Result r = rbdgen(args, dir());
    EXPECT_TRUE(isOneLineError(r)) << shown;
    EXPECT_EQ(r.err.rfind("rbdgen: error: ", 0), 0u) << shown << "-> " << r.err;
    EXPECT_TRUE(listTree(dir()).empty()) << shown;
  }
}

TEST_F(CliTest, NonexistentFileIsOneLineNamingTheFile)
{
  for(const char * cmd : {"generate", "info"})
  {
    const Result r = cmd == std::string("info") ? rbdgen({cmd, "no_such_robot.urdf"}, dir())
                                                : rbdgen({cmd, "no_such_robot.urdf", "--out", "o"}, dir());
    EXPECT_TRUE(isOneLineError(r)) << cmd;
    EXPECT_NE(r.err.find("no_such_robot.urdf"), std::string::npos) << r.err;
    EXPECT_TRUE(listTree(dir()).empty()) << cmd;
  }
}

// ---------------------------------------------------------------------------------------------
// generate: provenance

TEST_F(CliTest, GenerateWritesHeaderWithProvenance)
{
  struct Case
  {
    std::string robot;
    std::vector<std::string> extra;
    std::string ns, options;
  };
  const std::vector<Case> cases = {{"ur5e", {}, "ur5e", "fixed base"}, // default namespace: the robot name
                                   {"pendulum", {"--namespace", "my_pendulum"}, "my_pendulum", "fixed base"},
                                   {"quadruped", {"--floating-base"}, "quadruped", "floating base"}};
  for(const Case & c : cases)
  {
    const fs::path urdf = robot(c.robot);
    const std::string out = "out_" + c.robot;
    std::vector<std::string> args{"generate", urdf.string(), "--out", out};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    const Result r = rbdgen(args, dir());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const fs::path header = dir() / out / c.ns / "dynamics.hpp";
    ASSERT_TRUE(fs::is_regular_file(header)) << header;
    EXPECT_EQ(listTree(dir() / out), (std::vector<std::string>{c.ns, c.ns + "/dynamics.hpp"}));
    EXPECT_NE(r.out.find((fs::path(out) / c.ns / "dynamics.hpp").string()), std::string::npos) << r.out;

    const std::string text = readFile(header);
    const std::vector<std::string> ls = lines(text);
    ASSERT_GT(ls.size(), 10u);
    // Provenance on top: tool and version, "DO NOT EDIT", source name and hash, options.
    EXPECT_EQ(ls[0].rfind("// Generated by rbdgen " + projectVersion(), 0), 0u) << ls[0];
    EXPECT_NE(ls[0].find("DO NOT EDIT"), std::string::npos) << ls[0];
    const std::string hash = sha256sum(urdf);
    ASSERT_EQ(hash.size(), 64u);
    EXPECT_EQ(ls[1], "// Source: " + c.robot + ".urdf (sha256 " + hash + ")");
    EXPECT_EQ(ls[2], "// Options: " + c.options);
    EXPECT_NE(text.find("\nnamespace " + c.ns + "\n{"), std::string::npos);
    EXPECT_NE(text.find("} // namespace " + c.ns + "\n"), std::string::npos);
    // Only the file name is recorded, not where it was (see Determinism below).
    EXPECT_EQ(text.find(urdf.parent_path().string()), std::string::npos);
  }
}

TEST_F(CliTest, InstantiateWritesTheInstantiationsAndDeclaresThemExtern)
{
  const Result r = rbdgen({"generate", robot("pendulum").string(), "--out", "out", "--instantiate"}, dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(listTree(dir() / "out"), (std::vector<std::string>{"pendulum", "pendulum/dynamics.hpp", "pendulum/dynamics_double.cpp",
                                                                "pendulum/dynamics_float.cpp"}));
  const std::string header = readFile(dir() / "out/pendulum/dynamics.hpp");
  EXPECT_NE(header.find("// Options: fixed base, instantiated in dynamics_double.cpp and dynamics_float.cpp"), std::string::npos);
  // every extern declaration of the header has its definition in the source, for double and float
  for(const std::string scalar : {"double", "float"})
  {
    const std::string decl = "extern template Tangent<" + scalar + "> forward_dynamics<" + scalar + ">(";
    EXPECT_NE(header.find(decl), std::string::npos) << decl;
    const std::string source = readFile(dir() / ("out/pendulum/dynamics_" + scalar + ".cpp"));
    EXPECT_NE(source.find(decl.substr(7)), std::string::npos) << decl;
    EXPECT_NE(source.find("#include <pendulum/dynamics.hpp>"), std::string::npos);
  }
  // A scene has another API: --instantiate takes a URDF.
  const Result bad = rbdgen({"generate", "--scene", (fs::path(RBDGEN_SOURCE_DIR) / "scenes/pendulum_damped.xml").string(),
                             "--out", "o2", "--instantiate"},
                            dir());
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("--instantiate takes a URDF"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir() / "o2"));
}

TEST_F(CliTest, ProvenanceHashFollowsTheContent)
{
  // Same file name, one byte of mass changed: the recorded hash is that of the new content.
  std::string text = readFile(robot("pendulum"));
  const std::size_t at = text.find("<mass value=\"1\"/>");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 17, "<mass value=\"2\"/>");
  fs::create_directory(dir() / "edited");
  const fs::path urdf = dir() / "edited" / "pendulum.urdf";
  writeFile(urdf, text);
  ASSERT_EQ(rbdgen({"generate", urdf.string(), "--out", "out"}, dir()).code, 0);
  const std::string header = readFile(dir() / "out" / "pendulum" / "dynamics.hpp");
  const std::string hash = sha256sum(urdf);
  EXPECT_NE(hash, sha256sum(robot("pendulum")));
  EXPECT_NE(header.find("// Source: pendulum.urdf (sha256 " + hash + ")"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// generate: determinism and write-if-changed

TEST_F(CliTest, GenerationIsDeterministic)
{
  struct Case
  {
    std::string robot;
    std::vector<std::string> extra;
  };
  const std::vector<Case> cases = {{"ur5e", {}},
                                   {"humanoid", {"--floating-base"}},
                                   {"all_joints", {"--namespace", "aj"}},
                                   {"quadruped", {"--floating-base", "--base-link", "FL_calf"}}};
  for(const Case & c : cases)
  {
    const fs::path src = robot(c.robot);
    // A copy at another path with the same file name.
    const fs::path copyDir = dir() / ("elsewhere_" + c.robot) / "deeper";
    fs::create_directories(copyDir);
    fs::copy_file(src, copyDir / src.filename());
    const std::vector<std::pair<std::string, std::string>> runs = {
        {src.string(), "a"},                                           // absolute path
        {src.string(), "b"},                                           // another output dir
        {(copyDir / src.filename()).string(), "c"},                    // the copy, absolute
        {fs::relative(copyDir / src.filename(), dir()).string(), "d"}, // the copy, relative
    };
    std::vector<std::string> texts;
    for(const auto & [urdf, out] : runs)
    {
      std::vector<std::string> args{"generate", urdf, "--out", c.robot + "_" + out};
      args.insert(args.end(), c.extra.begin(), c.extra.end());
      const Result r = rbdgen(args, dir());
      ASSERT_EQ(r.code, 0) << c.robot << ": " << r.err;
      const std::vector<std::string> tree = listTree(dir() / (c.robot + "_" + out));
      ASSERT_EQ(tree.size(), 2u) << c.robot;
      texts.push_back(readFile(dir() / (c.robot + "_" + out) / tree[1]));
      ASSERT_GT(texts.back().size(), 1000u);
    }
    for(std::size_t k = 1; k < texts.size(); ++k) EXPECT_TRUE(texts[k] == texts[0]) << c.robot << ": run " << k << " differs";
    // Twice into the same directory: the same bytes.
    std::vector<std::string> args{"generate", src.string(), "--out", c.robot + "_a"};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    ASSERT_EQ(rbdgen(args, dir()).code, 0);
    const std::vector<std::string> tree = listTree(dir() / (c.robot + "_a"));
    ASSERT_EQ(tree.size(), 2u);
    EXPECT_TRUE(readFile(dir() / (c.robot + "_a") / tree[1]) == texts[0]) << c.robot;
  }
}

TEST_F(CliTest, UnchangedHeaderKeepsItsMtime)
{
  fs::create_directory(dir() / "src");
  const fs::path urdf = dir() / "src" / "pendulum.urdf";
  fs::copy_file(robot("pendulum"), urdf);
  const std::vector<std::string> args{"generate", urdf.string(), "--out", "out"};
  ASSERT_EQ(rbdgen(args, dir()).code, 0);
  const fs::path header = dir() / "out" / "pendulum" / "dynamics.hpp";
  const std::string before = readFile(header);
  // Back-date the header: a rewrite, even with the same bytes, would bring its mtime to now.
  const auto old = fs::last_write_time(header) - std::chrono::hours(24 * 365);
  fs::last_write_time(header, old);

  const Result again = rbdgen(args, dir());
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NE(again.out.find("dynamics.hpp"), std::string::npos); // still reported as the output
  EXPECT_TRUE(fs::last_write_time(header) == old) << "an unchanged header was rewritten";
  EXPECT_TRUE(readFile(header) == before);
  EXPECT_EQ(listTree(dir() / "out"), (std::vector<std::string>{"pendulum", "pendulum/dynamics.hpp"}));

  // Control: a changed URDF (the bob's mass) does rewrite it, leaving no temporary file behind.
  std::string text = readFile(urdf);
  text.replace(text.find("<mass value=\"1\"/>"), 17, "<mass value=\"3\"/>");
  writeFile(urdf, text);
  ASSERT_EQ(rbdgen(args, dir()).code, 0);
  EXPECT_TRUE(fs::last_write_time(header) > old);
  EXPECT_FALSE(readFile(header) == before);
  EXPECT_EQ(listTree(dir() / "out"), (std::vector<std::string>{"pendulum", "pendulum/dynamics.hpp"}));
}

TEST_F(CliTest, BatchWritesBatchHeaderBesideTheHeader)
{
  // --batch adds NS/batch.hpp and leaves dynamics.hpp as without it.
  ASSERT_EQ(rbdgen({"generate", robot("ur5e").string(), "--out", "plain"}, dir()).code, 0);
  const Result r = rbdgen({"generate", robot("ur5e").string(), "--out", "batch", "--batch"}, dir());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(listTree(dir() / "batch"), (std::vector<std::string>{"ur5e", "ur5e/batch.hpp", "ur5e/dynamics.hpp"}));
  EXPECT_NE(r.out.find("ur5e/batch.hpp"), std::string::npos);
  EXPECT_TRUE(readFile(dir() / "batch" / "ur5e" / "dynamics.hpp") == readFile(dir() / "plain" / "ur5e" / "dynamics.hpp"));
  const std::string batch = readFile(dir() / "batch" / "ur5e" / "batch.hpp");
  EXPECT_NE(batch.find("#include \"dynamics.hpp\""), std::string::npos);
  EXPECT_NE(batch.find("namespace ur5e"), std::string::npos);
  EXPECT_NE(batch.find("// Options: fixed base, batch"), std::string::npos);
  EXPECT_NE(batch.find("void forward_dynamics("), std::string::npos);
  EXPECT_EQ(batch.find("forward_dynamics_derivatives("), std::string::npos); // only with --derivatives
  // Deterministic: again, elsewhere, the same bytes; with --derivatives, their batch functions too.
  ASSERT_EQ(rbdgen({"generate", robot("ur5e").string(), "--out", "again", "--batch"}, dir()).code, 0);
  EXPECT_TRUE(readFile(dir() / "again" / "ur5e" / "batch.hpp") == batch);
  ASSERT_EQ(rbdgen({"generate", robot("ur5e").string(), "--out", "deriv", "--batch", "--derivatives"}, dir()).code, 0);
  EXPECT_NE(readFile(dir() / "deriv" / "ur5e" / "batch.hpp").find("void forward_dynamics_derivatives("), std::string::npos);
  // A scene: its header gets forward_kinematics, jacobian and center_of_mass (the batch API's), and its
  // batch header the scene's functions only; --derivatives adds the scene's <derivatives/>.
  const fs::path pendulum = fs::path(RBDGEN_SOURCE_DIR) / "scenes" / "pendulum_damped.xml";
  ASSERT_EQ(rbdgen({"generate", "--scene", pendulum.string(), "--out", "scene"}, dir()).code, 0);
  const Result scene = rbdgen({"generate", "--scene", pendulum.string(), "--out", "scene_batch", "--batch"}, dir());
  ASSERT_EQ(scene.code, 0) << scene.err;
  EXPECT_EQ(listTree(dir() / "scene_batch"), (std::vector<std::string>{"pendulum_damped", "pendulum_damped/batch.hpp",
                                                                       "pendulum_damped/dynamics.hpp"}));
  const std::string sceneHeader = readFile(dir() / "scene" / "pendulum_damped" / "dynamics.hpp");
  const std::string sceneBatchHeader = readFile(dir() / "scene_batch" / "pendulum_damped" / "dynamics.hpp");
  for(const char * fn : {"forward_kinematics(", "jacobian(Body body", "center_of_mass("})
  {
    EXPECT_EQ(sceneHeader.find(fn), std::string::npos) << fn; // not asked for by the scene
    EXPECT_NE(sceneBatchHeader.find(fn), std::string::npos) << fn;
  }
  EXPECT_EQ(sceneHeader.find("inverse_dynamics_derivatives("), std::string::npos);
  const std::string sceneBatch = readFile(dir() / "scene_batch" / "pendulum_damped" / "batch.hpp");
  EXPECT_NE(sceneBatch.find("// Options: batch."), std::string::npos);
  EXPECT_NE(sceneBatch.find("void gravity_torques("), std::string::npos); // the scene has gravity
  EXPECT_EQ(sceneBatch.find("const T * wrenches"), std::string::npos); // no external wrenches in this scene
  ASSERT_EQ(rbdgen({"generate", "--scene", pendulum.string(), "--out", "scene_deriv", "--derivatives"}, dir()).code, 0);
  EXPECT_NE(readFile(dir() / "scene_deriv" / "pendulum_damped" / "dynamics.hpp").find("inverse_dynamics_derivatives("),
            std::string::npos);
  // without gravity: no gravity_torques, in the header or its batch
  const fs::path floating = fs::path(RBDGEN_SOURCE_DIR) / "scenes" / "humanoid_zero_gravity.xml";
  ASSERT_EQ(rbdgen({"generate", "--scene", floating.string(), "--out", "zero_g", "--batch"}, dir()).code, 0);
  EXPECT_EQ(readFile(dir() / "zero_g" / "humanoid_zero_gravity" / "batch.hpp").find("gravity_torques("), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// info

TEST_F(CliTest, InfoPrintsTheTreeAndSizes)
{
  const fs::path urdf = robot("ur5e");
  const std::string text = readFile(urdf);
  // Independent of the loader: the link names and the joint types in the URDF text.
  const std::vector<std::string> links = allMatches(text, R"re(<link\s+name="([^"]+)")re");
  const std::vector<std::string> types = allMatches(text, R"re(<joint\s+name="[^"]+"\s+type="([^"]+)")re");
  ASSERT_EQ(links.size(), 8u);
  int nv = 0;
  for(const auto & t : types) nv += (t == "revolute" || t == "continuous" || t == "prismatic") ? 1 : 0;
  ASSERT_EQ(nv, 6);

  for(const bool floating : {false, true})
  {
    const Result r = floating ? rbdgen({"info", urdf.string(), "--floating-base"}, dir()) : rbdgen({"info", urdf.string()}, dir());
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.err, "");
    const int q = floating ? nv + 7 : nv, v = floating ? nv + 6 : nv;
    EXPECT_NE(r.out.find("nq = " + std::to_string(q) + ","), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("nv = " + std::to_string(v) + ","), std::string::npos) << r.out;
    // Every link on a line of its own, a child indented deeper than its parent (ur5e is a chain).
    const std::vector<std::string> ls = lines(r.out);
    std::size_t prevIndent = 0;
    for(std::size_t k = 0; k < links.size(); ++k)
    {
      const std::string & l = links[k];
      const auto it = std::find_if(ls.begin(), ls.end(), [&](const std::string & s) {
        const std::size_t b = s.find_first_not_of(' ');
        return b != std::string::npos && s.compare(b, l.size() + 1, l + " ") == 0;
      });
      ASSERT_NE(it, ls.end()) << "link " << l << " missing from:\n" << r.out;
      const std::size_t indent = it->find_first_not_of(' ');
      if(k > 0)
      {
        EXPECT_GT(indent, prevIndent) << l;
      }
      prevIndent = indent;
    }
    // Gravity torques of revolute joints are in N m.
    int torqueLines = 0;
    for(const auto & s : ls)
      if(s.find("tau[") != std::string::npos)
      {
        ++torqueLines;
        if(s.find("_joint][") != std::string::npos)
        {
          EXPECT_EQ(s.substr(s.size() - 4), " N m") << s;
        }
      }
    EXPECT_EQ(torqueLines, v);
  }
  EXPECT_TRUE(listTree(dir()).empty()); // info writes nothing
}

} // namespace
} // namespace clitest
