#pragma once
// Restart files. ParticleAlterAttrs.<step>.rst has the format of ParticleAlterAttrs.dat
// (global ID, current x y z, alterable attributes; 17 significant digits, so every double
// reads back to the same bits), with '#' header lines naming the step and the columns.
// Bonds.<step>.rst holds every bond's state (owner ID, partner ID, dead flag, bond
// attributes), so damage survives a restart. State.<step>.rst holds what the engine and
// the model keep between steps (the time step, the integrator's hold damping, the model's
// saveState()) and the number of bonds. A run restarted from a step continues bitwise as
// the uninterrupted run would have, whatever its number of steps. Reading is strict: a
// bonds file that is missing, of another step, cut short (fewer bonds than the state file
// says), with a self-bond, a one-sided bond, a bond listed twice, an ID not in the problem
// or a dead flag other than 0 or 1 is an error naming the file and line.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "engine/output.hpp"
#include "engine/problem.hpp"
#include "engine/simulation.hpp"

namespace pdq {

std::string restartPath(const std::string& dir, long step);
std::string bondRestartPath(const std::string& dir, long step);
std::string stateRestartPath(const std::string& dir, long step);

// The restart state of one step as the text of its files, in memory: what RestartOutput
// writes as files and a checkpoint (io/checkpoint.hpp) holds in one file. Parts not written
// at that step (fixed attributes of a non-periodic problem, bonds of a model without) are
// empty. The bonds, by far the largest part, may instead be held as their rows of numbers
// (owner ID, partner ID, dead flag, bond attributes; sorted by owner and partner): what a
// checkpoint's binary bonds are read into (formatting them as text costs far more than
// writing them).
struct RestartTexts {
  long step = -1;
  std::optional<std::string> state, fixed, bonds;
  std::optional<std::vector<double>> bondRows;
  std::string particles;
};

// The state at out.step as text, handed to `sink` on rank 0 (nothing elsewhere) part after
// part in this order, each in pieces of about 8192 particles, so that rank 0 never holds a
// whole part; collective. Without `bonds` the bonds are left out (a checkpoint gathers them
// in its own form); the state still counts them.
enum class RestartPart { STATE, FIXED, BONDS, PARTICLES };
using RestartSink = std::function<void(RestartPart, const std::string&)>;
void restartParts(OutputContext& out, bool bonds, const RestartSink& sink);

// What each part is called in messages: its file (RestartOutput's names in a folder).
struct RestartNames {
  std::string particles, state, fixed, bonds;
};
RestartNames restartNames(const std::string& dir, long step);

// Removes the restart files in `dir` of steps after `step` (every one when `step` < 0).
void removeRestartFiles(const std::string& dir, long step);

class RestartOutput final : public Output {
 public:
  RestartOutput(long every, bool atEnd) : Output(every), atEnd_(atEnd) {}
  bool atEnd() const override { return atEnd_; }
  bool capturesState() const override { return true; }
  void begin(OutputContext& out, bool resumed) override;
  void write(OutputContext& out) override;

 private:
  bool atEnd_;
  long lastWritten_ = -1;
};

// Replaces the problem's alterable attributes by those of the restart file `path` (every
// particle must be there, and nothing else), sets the first step, and returns the bonds
// of the companion Bonds.<step>.rst (none if the model has no bonds) and the state of
// State.<step>.rst, for Simulation::restore.
RestartState readRestart(const std::string& path, Problem& problem);
// The same from texts in memory, checked just as strictly.
RestartState parseRestart(const RestartTexts& texts, const RestartNames& names, Problem& problem);

}  // namespace pdq
