// The TOML scenario reader on any text, beside two small particle files it may name
// (fixed = "fixed.dat", alter = "alter.dat").
#include "engine/error.hpp"
#include "fuzz_support.hpp"
#include "scenario/scenario.hpp"

using namespace pdq;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::limitMemory();
  const std::string& d = fuzz::workDir();
  fuzz::writeFile(d + "/fixed.dat", "# id X Y Z\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 1 1 0\n");
  fuzz::writeFile(d + "/alter.dat",
                  "# id x y z vx vy vz\n0 0 0 0 0 0 0\n1 1 0 0 0 0 0\n2 0 1 0 0 0 0\n"
                  "3 1 1 0 0 0 0\n");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = fuzz::workDir() + "/scenario.toml";
  fuzz::writeFile(path, std::string(reinterpret_cast<const char*>(data), size));
  try {
    readScenario(path);
  } catch (const Error&) {
  }
  return 0;
}
