// Restart files of the tests' breaking spring lattice (tests/cli/spring_case.hpp): the
// input is ParticleAlterAttrs.10.rst, Bonds.10.rst and State.10.rst, separated by
// lines "%%".
#include "engine/error.hpp"
#include "fuzz_support.hpp"
#include "io/restart.hpp"

using namespace pdq;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& d = fuzz::workDir();
  const auto parts = fuzz::split(data, size, 3);
  fuzz::writeFile(restartPath(d, 10), parts[0]);
  fuzz::writeFile(bondRestartPath(d, 10), parts[1]);
  fuzz::writeFile(stateRestartPath(d, 10), parts[2]);
  try {
    readRestart(restartPath(d, 10), fuzz::springProblem());
  } catch (const Error&) {
  }
  return 0;
}
