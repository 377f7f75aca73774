// The same run three ways gives the same bits: from the TOML scenario, from the thesis's
// .dat files `pdq prep` wrote for it (for every example scenario too), and under mpirun
// -np 2 (and 3, with a chosen grid).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "pdq_process.hpp"
#include "spring_case.hpp"

using pdq::test::freshDir;
using pdq::test::readFile;
using pdq::test::runPdq;
using pdq::test::springCase;

namespace {
void expectSameFinalState(const std::string& a, const std::string& b) {
  for (const char* f : {"ParticleAlterAttrs.40.rst", "Bonds.40.rst"}) {
    const std::string x = readFile(a + "/" + f), y = readFile(b + "/" + f);
    ASSERT_FALSE(x.empty()) << a << "/" << f;
    EXPECT_TRUE(x == y) << f << " differs between " << a << " and " << b;
  }
}
}  // namespace

TEST(CliEquivalence, ScenarioAndThesisFilesAgreeBitwise) {
  const std::string dir = freshDir("equivalence_dat");
  const std::string sc = springCase(dir, 40);
  ASSERT_EQ(runPdq({"prep", sc, "-o", "dat"}, dir).code, 0);
  auto r = runPdq({"run", sc, "-q", "--out", "from_toml"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  r = runPdq({"run", "dat", "-q", "--out", "from_dat"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  expectSameFinalState(dir + "/from_toml", dir + "/from_dat");
  // The time history of the monitored particles too.
  EXPECT_EQ(readFile(dir + "/from_toml/timehist.dat"), readFile(dir + "/from_dat/timehist.dat"));
}

// Every example scenario shipped in examples/ (a few steps of each): `pdq prep X.toml` then
// `pdq run` of the folder ends in the same bits as `pdq run X.toml`.
TEST(CliEquivalence, EveryExampleThroughItsThesisFilesAgreesBitwise) {
  namespace fs = std::filesystem;
  const std::string dir = freshDir("equivalence_examples");
  int examples = 0;
  for (const auto& e : fs::recursive_directory_iterator(pdq::test::sourceDir() + "/examples")) {
    if (e.path().extension() != ".toml" || e.path().parent_path().filename() == "plugin") continue;
    const std::string name = e.path().stem().string();
    SCOPED_TRACE(e.path().string());
    const std::string steps = "12";
    auto r = runPdq({"prep", e.path().string(), "-o", name + "_dat"}, dir);
    ASSERT_EQ(r.code, 0) << r.all();
    r = runPdq({"run", e.path().string(), "-q", "--steps", steps, "--out", name + "_toml"}, dir);
    ASSERT_EQ(r.code, 0) << r.all();
    r = runPdq({"run", name + "_dat", "-q", "--steps", steps, "--out", name + "_from_dat"}, dir);
    ASSERT_EQ(r.code, 0) << r.all();
    const std::string rst = "/ParticleAlterAttrs." + steps + ".rst";
    const std::string a = readFile(dir + "/" + name + "_toml" + rst);
    ASSERT_FALSE(a.empty()) << name << "_toml" << rst;
    EXPECT_TRUE(a == readFile(dir + "/" + name + "_from_dat" + rst))
        << name << ": the .dat route differs from the scenario";
    ++examples;
  }
  EXPECT_GE(examples, 11);  // spring, lj and the nine MPLM examples
}

TEST(CliEquivalence, MpirunMatchesOneRankBitwise) {
  const std::string dir = freshDir("equivalence_np");
  const std::string sc = springCase(dir, 40);
  auto r = runPdq({"run", sc, "-q", "--out", "np1"}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  r = runPdq({"run", sc, "-q", "--out", "np2"}, dir, 2);
  ASSERT_EQ(r.code, 0) << r.all();
  expectSameFinalState(dir + "/np1", dir + "/np2");
  EXPECT_EQ(readFile(dir + "/np1/history.csv"), readFile(dir + "/np2/history.csv"));
  // A 1 x 3 grid, chosen in the scenario.
  const std::string grid = springCase(dir, 40, "\n", "grid.toml");
  std::string text = readFile(grid);
  text.replace(text.find("min_cell_size"), 0, "procs = [1, 3, 1]\n");
  pdq::test::writeFile(grid, text);
  r = runPdq({"run", grid, "-q", "--out", "np3"}, dir, 3);
  ASSERT_EQ(r.code, 0) << r.all();
  expectSameFinalState(dir + "/np1", dir + "/np3");
}

TEST(CliEquivalence, ErrorsUnderMpirunArePrintedOnceWithNoOutput) {
  const std::string dir = freshDir("equivalence_error");
  const std::string sc = springCase(dir, 40);
  std::string text = readFile(sc);
  text.replace(text.find("horizon = 1.5"), 13, "horizon = 1.5\ndampnig = 0.1");
  pdq::test::writeFile(sc, text);
  const auto r = runPdq({"run", sc}, dir, 2);
  EXPECT_NE(r.code, 0);
  EXPECT_EQ(r.code, 1) << r.all();
  const std::string msg = "lattice.toml:9: unknown parameter 'dampnig'";
  ASSERT_NE(r.err.find(msg), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find(msg), r.err.rfind(msg)) << "printed more than once: " << r.err;
  EXPECT_TRUE(pdq::test::filesUnder(dir + "/out").empty());
}
