#pragma once
// Scenario files (TOML; every field is documented in docs/scenario.md):
//
//     steps = 2000
//     [model]                 name = "spring", then the model's parameters
//     [particles]             fixed = "...dat", alter = "...dat"   (relative to this file)
//                             or generator = "square" and the generator's parameters
//     [[particles.set]]       attribute values by region (velocities, supports, loads)
//     [decomposition]         procs, min_cell_size, margin, periodic, box_lo, box_hi, dimension
//     [output]                dir, restart_every, history_every, history_ids, globals_every
//     [output.paraview], [output.picture]
//     [strength]              options of the strength search (pdq strength)
//
// Every value keeps its file and line; a key nobody reads is an error at its line with
// the nearest known key suggested.
#include <optional>
#include <string>
#include <vector>

#include "engine/params.hpp"
#include "engine/problem.hpp"
#include "prep/generator.hpp"

namespace pdq {

struct Scenario {
  Problem problem;
  // The model's parameters as written (for `pdq prep`, which writes pdQUserInput.dat).
  Params modelParams{"[model]"};
  // The generator that made the particles and its [particles] parameters (empty when they
  // came from files): the strength study reads the specimen's geometry from them.
  std::string generator;
  Params generatorParams{"[particles]"};
  // The [strength] table: options of `pdq strength` (studies/strength_study.hpp), checked
  // there; `--set` items override them.
  Params strength{"[strength]"};
  // [strength.model]: model parameters for the search's trials only (e.g. a larger time
  // step by rotary-inertia scaling, which leaves statics unchanged).
  Params strengthModel{"[strength.model]"};
  // What each [[particles.set]] entry selected (pdq info lists it).
  struct SetCount {
    int line;
    std::string attribute;
    std::size_t particles;
  };
  std::vector<SetCount> setCounts;
  // With readScenario(path, true): what the generator would make, or the number of
  // particles in the particle files (no lattice then).
  std::optional<SizeEstimate> estimate;
};

// Reads a TOML scenario: creates and configures the model, builds or reads the particles
// and checks everything that can be checked before a run (InputError with file:line).
// `estimateOnly`: the particles are not made, their sizes estimated instead (`estimate`;
// none for a generator without an estimate), and the tables after [particles]
// ([[particles.set]], [solver.control], [decomposition], [output]) are not read.
Scenario readScenario(const std::string& path, bool estimateOnly = false);

// A scenario file, or a folder holding the thesis's .dat files (io/thesis_input.hpp).
Scenario loadScenario(const std::string& path);

}  // namespace pdq
