#pragma once
// What the fuzz targets share: a private folder to write their inputs into, the input cut
// into files, and the tests' spring lattice that restart files and checkpoints are read for.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/problem.hpp"

namespace pdq::fuzz {

// A folder of this process's own, made once (removed at exit).
const std::string& workDir();
void writeFile(const std::string& path, const std::string& text);
// The input cut at each "\n%%\n" into at most `parts` texts (the last keeps the rest);
// missing parts are empty.
std::vector<std::string> split(const std::uint8_t* data, std::size_t size, std::size_t parts);
// Sets the memory pdq believes the machine has, so that a scenario asking for more is
// refused before it allocates rather than exhausting the fuzzer's limit.
void limitMemory();
// The tests' breaking spring lattice (tests/cli/spring_case.hpp, 20 steps), written into
// workDir() at the first call (lattice.toml, fixed.dat, alter.dat), after limitMemory().
// Returns the scenario's path.
const std::string& springCase();
// The spring lattice's problem, read once, with the particles and run it was read with (a
// restart replaces them).
Problem& springProblem();

}  // namespace pdq::fuzz
