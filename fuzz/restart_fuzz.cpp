// Restart files for a small breaking spring lattice (4 x 4, bonds to its 8 neighbours):
// the input is ParticleAlterAttrs.10.rst, Bonds.10.rst and State.10.rst, separated by
// lines "%%".
#include "engine/error.hpp"
#include "fuzz_support.hpp"
#include "io/restart.hpp"
#include "scenario/scenario.hpp"

using namespace pdq;

namespace {
const char* kScenario = R"(steps = 20
[model]
name = "spring"
critical_stretch = 0.02
dt = 0.05
horizon = 1.5
[particles]
generator = "square"
nx = 4
ny = 4
)";
}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::limitMemory();
  fuzz::writeFile(fuzz::workDir() + "/lattice.toml", kScenario);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& d = fuzz::workDir();
  const auto parts = fuzz::split(data, size, 3);
  fuzz::writeFile(restartPath(d, 10), parts[0]);
  fuzz::writeFile(bondRestartPath(d, 10), parts[1]);
  fuzz::writeFile(stateRestartPath(d, 10), parts[2]);
  Scenario sc = readScenario(d + "/lattice.toml");
  try {
    readRestart(restartPath(d, 10), sc.problem);
  } catch (const Error&) {
  }
  return 0;
}
