#pragma once
// Checkpoints: a run's complete state at a step in one file, <output>/checkpoint.<step>.ckpt
// (the step zero-padded to 12 digits, so names sort as steps do), from which
// `pdq run --resume <output>` continues bitwise as the uninterrupted run. A checkpoint holds
// the texts of the step's restart files (io/restart.hpp: particles, the integrator's and
// the model's state, the time step) and its bonds and their state in a compact binary
// form, read back into the rows a bonds file holds (RestartTexts::bondRows), so both are
// checked by the same code as strictly, behind a header (step, time, Δt, the time step
// the model set up, a hash of the scenario) and followed by a CRC-32 of everything before
// it. Written to a temporary, synced and renamed (engine/atomic_file.hpp); the newest
// `kept` are kept. Layout (native byte order, as the machine that wrote it; a checkpoint
// is for resuming on the same kind of machine):
//   "PDQCKPT1"  u64 step  f64 time  f64 dt  f64 setup dt  u64 scenario hash  u32 parts
//   per part: u32 name length, name ("state", "fixed", "bond codes", "particles"),
//             u64 length, bytes (text but for the bond codes)
//   u32 CRC-32 of all the bytes above
// The bond codes, the same bytes on any number of ranks:
//   u32 attributes per bond A; per attribute its dictionary: u8 size, f64 values
//   u64 particles with bonds, u64 bonds
//   per particle in ID order: varint ID - previous particle's ID (the first: its ID),
//     varint bond count, per bond in partner order: varint (zigzag(partner ID - previous
//     partner's ID, the first: the particle's) << 1 | dead flag)
//   per bond in the same order, A attribute codes: a byte k < 255, value k of the
//     attribute's dictionary, or 255 and the value's 8 bytes
// (varint: 7 bits a byte, low first, the top bit set on all but the last; zigzag(d) =
// 2d for d >= 0, -2d - 1 below). Checkpoints of earlier versions, with the bonds as
// "bonds" (text) or "bond rows" (f64 owner ID, partner ID, dead flag, attributes, row
// after row), are read too.
#include <cstdint>
#include <string>
#include <vector>

#include "engine/output.hpp"
#include "engine/problem.hpp"
#include "engine/simulation.hpp"

namespace pdq {

std::string checkpointPath(const std::string& dir, long step);
// The steps of the checkpoints in `dir` (by name), oldest first.
std::vector<long> checkpointSteps(const std::string& dir);

// A hash of a scenario: its input file's bytes (or those of a folder's .dat files in name
// order: the thesis's input) and the particles it starts from (`initial`, before a restart
// replaces them), so that particle files it names are covered too.
std::uint64_t scenarioHash(const std::string& input, const ParticleSet& initial);

class CheckpointOutput final : public Output {
 public:
  CheckpointOutput(const OutputSettings& settings, std::uint64_t scenarioHash);
  bool capturesState() const override { return true; }
  bool writtenOnStop() const override { return true; }
  bool atEnd() const override { return true; }  // a finished run can be continued further
  bool timed() const override { return minutes_ > 0; }
  bool requested() override;
  // Removes the checkpoints and restart files of steps after a resumed run's first (those
  // it found damaged, or a killed run's), or all of them in a run started afresh (an
  // earlier run's in a reused folder).
  void begin(OutputContext& out, bool resumed) override;
  void write(OutputContext& out) override;

 private:
  double minutes_;
  long kept_;
  std::uint64_t hash_;
  double last_;  // when the last checkpoint was written (or the run started), seconds
  long lastWritten_ = -1;
};

struct Resumed {
  RestartState state;
  std::string path;                   // the checkpoint resumed from
  std::vector<std::string> warnings;  // the newer checkpoints skipped, and why
};

// Loads the newest valid checkpoint in `dir` into `problem` (its particles and first step,
// as readRestart does) and returns the rest of its state for Simulation::restore. One cut
// short, damaged (checksum) or unreadable is skipped with a warning naming it; one of
// another scenario (its hash: another input, time step or particles) is refused unless
// `force` (which continues with this run's time step). InputError when there is none.
Resumed resumeFromCheckpoint(const std::string& dir, std::uint64_t scenarioHash, bool force,
                             Problem& problem);

}  // namespace pdq
