// Checkpoints of the tests' breaking spring lattice (tests/cli/spring_case.hpp): the input
// is checkpoint.000000000010.ckpt without its last four bytes, the CRC-32, which the target
// appends (computed), so that the fuzzer reaches the header, the parts and the restart
// texts behind the checksum (a wrong checksum is tested in the suite). Resumed as
// `pdq run --resume --force` does, so that a checkpoint of another scenario is read too.
#include "engine/checksum.hpp"
#include "engine/error.hpp"
#include "fuzz_support.hpp"
#include "io/checkpoint.hpp"

using namespace pdq;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& d = fuzz::workDir();
  std::string bytes(reinterpret_cast<const char*>(data), size);
  const std::uint32_t crc = crc32(bytes.data(), bytes.size());
  bytes.append(reinterpret_cast<const char*>(&crc), sizeof crc);
  fuzz::writeFile(checkpointPath(d, 10), bytes);
  try {
    resumeFromCheckpoint(d, 0, true, fuzz::springProblem());
  } catch (const Error&) {
  }
  return 0;
}
