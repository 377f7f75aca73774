#pragma once
// The thesis's input files (appendix A.2), kept readable and writable:
//   pdQInput.dat        nPX nPY nPZ, minimum cell size, number of time steps (five numbers,
//                       free format; -1 steps: as long as ramp_time + hold_time), then
//                       optional engine settings as `key value...` lines: margin, dimension,
//                       periodic (3 flags), box_lo, box_hi (3 numbers each), restart_every,
//                       history_every, history_ids, globals_every and the load protocol's
//                       load_scale, ramp_time, hold_time, hold_damping_ratio
//   pdQUserInput.dat    `model NAME`, then the model's parameters as `key value...` lines
//   ParticleFixedAttrs.dat  per record: global ID, reference x y z, the model's fixed attributes
//   ParticleAlterAttrs.dat  per record: global ID, current x y z, the model's alterable ones
// Outputs ParticleAlterAttrs.<step>.rst have the alterable file's format, so a run restarts
// from one (io/restart.hpp).
#include <string>

#include "engine/particle_set.hpp"
#include "engine/problem.hpp"
#include "engine/schema.hpp"

namespace pdq {

// Reads the four files in `dir` and creates and configures the model.
Problem readThesisInput(const std::string& dir);

// Reads the two particle files for a model's schema: counts, numbers, finite values,
// unique IDs and matching ID sets are checked, with file and line in every error.
ParticleSet readParticleFiles(const std::string& fixedPath, const std::string& alterPath,
                              const Schema& schema);

// Writes a problem as the thesis's four files in `dir` (what `pdq prep` does); without a
// minimum cell size of its own, pdQInput.dat gets the model's.
void writeThesisInput(const std::string& dir, const Problem& problem, const Params& modelParams);
void writeParticleFiles(const std::string& dir, const ParticleSet& particles, const Schema& schema);

}  // namespace pdq
