// The out-of-tree model of examples/plugin: pdq is installed to a temporary prefix, the
// plugin is built there with CMake's find_package(pdq), and the installed pdq runs its
// scenario with --plugin.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "pdq_process.hpp"

namespace fs = std::filesystem;
using namespace pdq::test;
using testing::HasSubstr;

TEST(CliPlugin, OutOfTreeModelBuiltAgainstTheInstalledHeaders) {
  const std::string dir = freshDir("plugin");
  const std::string prefix = dir + "/prefix", build = dir + "/build";
  ASSERT_EQ(std::system(("cmake --install '" PDQ_BINARY_DIR "' --prefix '" + prefix +
                         "' > '" + dir + "/install.log' 2>&1")
                            .c_str()),
            0)
      << readFile(dir + "/install.log");
  const std::string src = sourceDir() + "/examples/plugin";
  ASSERT_EQ(std::system(("cmake -S '" + src + "' -B '" + build + "' -DCMAKE_BUILD_TYPE=Release " +
                         "-DCMAKE_PREFIX_PATH='" + prefix + "' > '" + dir + "/configure.log' 2>&1")
                            .c_str()),
            0)
      << readFile(dir + "/configure.log");
  ASSERT_EQ(std::system(("cmake --build '" + build + "' -j2 > '" + dir + "/build.log' 2>&1").c_str()),
            0)
      << readFile(dir + "/build.log");
  const std::string lib = build + "/libmorse.so";
  ASSERT_TRUE(fs::exists(lib));
  fs::copy(src + "/cluster.toml", dir + "/cluster.toml");

  // The installed pdq, so the plugin and the command share one libpdq.
  setenv("PDQ_EXE", (prefix + "/bin/pdq").c_str(), 1);
  auto r = runPdq({"list", "--plugin", lib}, dir);
  EXPECT_EQ(r.code, 0) << r.all();
  EXPECT_THAT(r.out, HasSubstr("morse"));
  EXPECT_THAT(r.out, HasSubstr("morse_block"));
  r = runPdq({"run", "cluster.toml", "--steps", "200", "-q"}, dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("unknown model 'morse'"));
  r = runPdq({"run", "cluster.toml", "--steps", "200", "--plugin", lib}, dir);
  ASSERT_EQ(r.code, 0) << r.all();
  // The compressed cube springs back: kinetic energy appears, and the total stays put.
  const std::string hist = readFile(dir + "/cluster_out/history.csv");
  ASSERT_THAT(hist, HasSubstr("kinetic"));
  // Under mpirun too, with the same bits.
  r = runPdq({"run", "cluster.toml", "--steps", "200", "--plugin", lib, "-q", "--out", "np2"}, dir,
          2);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_EQ(readFile(dir + "/np2/history.csv"), hist);
  EXPECT_EQ(readFile(dir + "/np2/ParticleAlterAttrs.200.rst"),
            readFile(dir + "/cluster_out/ParticleAlterAttrs.200.rst"));
  unsetenv("PDQ_EXE");
}
