// Every scenario under examples/ runs as it is (shortened to a few steps) and its
// thesis-format files can be written by pdq prep.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "pdq_process.hpp"

namespace fs = std::filesystem;
using namespace pdq::test;

TEST(CliExamples, EveryScenarioRuns) {
  std::vector<fs::path> scenarios;
  for (const auto& e : fs::recursive_directory_iterator(sourceDir() + "/examples"))
    if (e.path().extension() == ".toml" && e.path().parent_path().filename() != "plugin")
      scenarios.push_back(e.path());
  std::sort(scenarios.begin(), scenarios.end());
  ASSERT_GE(scenarios.size(), 1u);
  for (const auto& sc : scenarios) {
    SCOPED_TRACE(sc.string());
    const std::string dir = freshDir("example_" + sc.stem().string());
    auto r = runPdq({"info", sc.string()}, dir);
    EXPECT_EQ(r.code, 0) << r.all();
    r = runPdq({"run", sc.string(), "--steps", "5", "-q", "--out", "out"}, dir);
    EXPECT_EQ(r.code, 0) << r.all();
    EXPECT_TRUE(fs::exists(dir + "/out/ParticleAlterAttrs.5.rst"));
    r = runPdq({"prep", sc.string(), "-o", "dat"}, dir);
    EXPECT_EQ(r.code, 0) << r.all();
    EXPECT_TRUE(fs::exists(dir + "/dat/ParticleFixedAttrs.dat"));
  }
}
