#pragma once
// Sizes before allocation: a generator (or reader) that is about to make `count`
// particles of `bytesEach` bytes checks first that they fit in the memory the machine has
// available, so that a scenario asking for 10^9 particles is refused at once with the
// estimate instead of running the machine out of memory.
#include <string>

#include "engine/error.hpp"
#include "engine/schema.hpp"

namespace pdq {

// Too large for the machine: the scenario reader adds the file and line of the request.
class MemoryError : public Error {
 public:
  using Error::Error;
};

// Bytes available to pdq: MemAvailable of /proc/meminfo, or the environment's
// PDQ_MEMORY_LIMIT (a number of bytes, with an optional K, M, G or T suffix) when set.
double availableMemory();

// Throws MemoryError ("would make about 1e+09 particles, at least 88 GB for their
// attributes alone; this machine has N GB available ...") when `count` particles of
// `bytesEach` bytes exceed the available memory. `what`: who makes them.
void checkParticleCount(double count, double bytesEach, const std::string& what);

// The bytes of the engine's particle and bond tables (a model's neighbour lists and
// scratch come on top): `local` particles' fixed and alterable rows (owned and ghosts),
// `owned` ones' integration rows and bond offsets, and `bondEntries` bonds (each held by
// both its particles).
double tableBytes(const Schema& schema, double local, double owned, double bondEntries);

// "1.5 GB", "320 MB", ...
std::string byteText(double bytes);

}  // namespace pdq
