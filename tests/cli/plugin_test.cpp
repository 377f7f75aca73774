// The out-of-tree model of examples/plugin: pdq is installed to a temporary prefix, the
// plugin is built there with CMake's find_package(pdq), and the installed pdq runs its
// scenario with --plugin.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "pdq_process.hpp"

namespace fs = std::filesystem;
using namespace pdq::test;
using testing::HasSubstr;
using testing::Not;

TEST(CliPlugin, OutOfTreeModelBuiltAgainstTheInstalledHeaders) {
  const std::string dir = freshDir("plugin");
  const std::string prefix = dir + "/prefix", build = dir + "/build";
  ASSERT_EQ(std::system(("cmake --install '" PDQ_BINARY_DIR "' --prefix '" + prefix + "' > '" +
                         dir + "/install.log' 2>&1")
                            .c_str()),
            0)
      << readFile(dir + "/install.log");
  const std::string src = sourceDir() + "/examples/plugin";
  // A model needs no MPI headers: the plugin's source compiles with the installed include
  // directory alone (MPI's is not on the compiler's default path), and reaches no mpi.h.
  ASSERT_EQ(std::system((std::string(PDQ_CXX) + " -std=c++20 -M -I'" + prefix + "/include/pdq' '" +
                         src + "/morse.cpp' > '" + dir + "/deps.log' 2>&1")
                            .c_str()),
            0)
      << readFile(dir + "/deps.log");
  EXPECT_THAT(readFile(dir + "/deps.log"), HasSubstr("engine/model.hpp"));
  EXPECT_THAT(readFile(dir + "/deps.log"), Not(HasSubstr("mpi.h")));
  ASSERT_EQ(std::system(("cmake -S '" + src + "' -B '" + build + "' -DCMAKE_BUILD_TYPE=Release " +
                         "-DCMAKE_EXPORT_COMPILE_COMMANDS=ON -DCMAKE_PREFIX_PATH='" + prefix +
                         "' > '" + dir + "/configure.log' 2>&1")
                            .c_str()),
            0)
      << readFile(dir + "/configure.log");
  ASSERT_EQ(
      std::system(("cmake --build '" + build + "' -j2 > '" + dir + "/build.log' 2>&1").c_str()), 0)
      << readFile(dir + "/build.log");
  // find_package(pdq) hands the plugin no MPI include directory.
  const std::string commands = readFile(build + "/compile_commands.json");
  EXPECT_THAT(commands, HasSubstr("morse.cpp"));
  EXPECT_THAT(commands, Not(HasSubstr(PDQ_MPI_INCLUDE_DIR)));
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
  ASSERT_THAT(hist, HasSubstr("step,time,kinetic,potential\n"));
  std::istringstream rows(hist.substr(hist.find('\n') + 1));
  std::string row;
  double first = 0, maxKinetic = 0, maxDrift = 0;
  int n = 0;
  while (std::getline(rows, row)) {
    long step = 0;
    double time = 0, kinetic = 0, potential = 0;
    ASSERT_EQ(std::sscanf(row.c_str(), "%ld,%lf,%lf,%lf", &step, &time, &kinetic, &potential), 4);
    if (step == 0) continue;  // no force evaluated yet: no potential energy
    if (n++ == 0) first = kinetic + potential;
    maxKinetic = std::max(maxKinetic, kinetic);
    maxDrift = std::max(maxDrift, std::abs(kinetic + potential - first) / std::abs(first));
  }
  EXPECT_EQ(n, 10);
  EXPECT_GT(maxKinetic, 5.0);  // the compressed cube springs back
  EXPECT_LT(maxDrift, 1e-3);   // and keeps its energy (leapfrog, half-step kinetic energy)
  // Under mpirun too, with the same bits.
  r = runPdq({"run", "cluster.toml", "--steps", "200", "--plugin", lib, "-q", "--out", "np2"}, dir,
             2);
  ASSERT_EQ(r.code, 0) << r.all();
  EXPECT_EQ(readFile(dir + "/np2/history.csv"), hist);
  EXPECT_EQ(readFile(dir + "/np2/ParticleAlterAttrs.200.rst"),
            readFile(dir + "/cluster_out/ParticleAlterAttrs.200.rst"));
  unsetenv("PDQ_EXE");
}
