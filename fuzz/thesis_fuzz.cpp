// The thesis's four input files: the input is pdQInput.dat, pdQUserInput.dat,
// ParticleFixedAttrs.dat and ParticleAlterAttrs.dat, separated by lines "%%".
#include "engine/error.hpp"
#include "fuzz_support.hpp"
#include "io/thesis_input.hpp"

using namespace pdq;

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fuzz::limitMemory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& d = fuzz::workDir();
  const auto parts = fuzz::split(data, size, 4);
  const char* names[] = {"pdQInput.dat", "pdQUserInput.dat", "ParticleFixedAttrs.dat",
                         "ParticleAlterAttrs.dat"};
  for (int i = 0; i < 4; ++i) fuzz::writeFile(d + "/" + names[i], parts[i]);
  try {
    readThesisInput(d);
  } catch (const Error&) {
  }
  return 0;
}
