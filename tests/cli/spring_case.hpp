#pragma once
// A small breaking spring lattice as a scenario with particle files: 16 x 8 particles at
// unit spacing, the upper half pulled apart along X fast enough that springs break, the
// lower half slowly; velocities set by [[particles.set]] entries.
#include <string>

#include "pdq_process.hpp"

namespace pdq::test {

// The case's texts: fixed.dat, alter.dat and the scenario (its output goes to out/), with
// `extra` appended to the scenario. The fuzz targets of restart files and checkpoints read
// them too.
struct SpringCaseTexts {
  std::string fixed, alter, scenario;
};

inline SpringCaseTexts springCaseTexts(long steps, const std::string& extra = "") {
  std::string fixed = "# id X Y Z\n", alter = "# id x y z vx vy vz\n";
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 16; ++i) {
      const std::string id = std::to_string(j * 16 + i), x = std::to_string(i),
                        y = std::to_string(j);
      fixed += id + " " + x + " " + y + " 0\n";
      alter += id + " " + x + " " + y + " 0 0 0 0\n";
    }
  const std::string scenario =
      "# a breaking spring lattice\n"
      "steps = " +
      std::to_string(steps) + "\n" +
      R"(
[model]
name = "spring"
critical_stretch = 0.02
dt = 0.05
horizon = 1.5

[particles]
fixed = "fixed.dat"
alter = "alter.dat"

[[particles.set]]          # upper half: vx = 0.05 (X - 7.5)
attribute = "vx"
value = -0.375
gradient = [0.05, 0, 0]
y = [4, 7]

[[particles.set]]          # lower half: ten times slower
attribute = "vx"
value = -0.0375
gradient = [0.005, 0, 0]
y = [0, 3]

[[particles.set]]
attribute = "vy"
value = -0.0175
gradient = [0, 0.005, 0]

[decomposition]
min_cell_size = 1.5

[output]
dir = "out"
restart_every = 10
globals_every = 5
history_every = 5
history_ids = [0, 127]
)" + extra;
  return {fixed, alter, scenario};
}

// Writes <dir>/fixed.dat, <dir>/alter.dat and <dir>/<name> (the scenario, whose output
// goes to <dir>/out). Returns the scenario's path.
inline std::string springCase(const std::string& dir, long steps, const std::string& extra = "",
                              const std::string& name = "lattice.toml") {
  const SpringCaseTexts t = springCaseTexts(steps, extra);
  writeFile(dir + "/fixed.dat", t.fixed);
  writeFile(dir + "/alter.dat", t.alter);
  writeFile(dir + "/" + name, t.scenario);
  return dir + "/" + name;
}

}  // namespace pdq::test
