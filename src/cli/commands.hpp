#pragma once
// The pdq subcommands. Each runs on every rank (under mpirun or alone); files are
// written by rank 0 or collectively through the engine's outputs.
#include <string>
#include <vector>

#include "cli/progress.hpp"

namespace pdq::cli {

struct RunOptions {
  std::string input;       // scenario .toml or a folder of the thesis's .dat files
  std::string restart;     // ParticleAlterAttrs.<step>.rst to continue from
  std::string resume;      // output folder whose newest valid checkpoint to continue from
  bool force = false;      // resume even from a checkpoint of another scenario or time step
  std::string out;         // output folder (overrides the scenario's)
  long steps = -1;         // last step (overrides the scenario's)
  double maxWallTime = 0;  // seconds; > 0: stop with a checkpoint before this much wall time
  Verbosity verbosity = Verbosity::Normal;
};
// Returns Ok, or Interrupted when a signal or the wall-time limit stopped the run early.
int runCommand(const RunOptions& o);

struct InfoOptions {
  std::string input;
  int ranks = 0;  // also show the processor grid for this many ranks
};
void infoCommand(const InfoOptions& o);

struct PrepOptions {
  std::string input;  // scenario .toml
  std::string out;    // folder for pdQInput.dat, pdQUserInput.dat, Particle*Attrs.dat
};
void prepCommand(const PrepOptions& o);

struct PictureCommandOptions {
  std::string input;             // the scenario (or .dat folder) the run came from
  std::string restart;           // ParticleAlterAttrs.<step>.rst; empty: the latest in the output
  std::string out;               // picture file; empty: <output>/<name>_<step>.<format>
  std::vector<std::string> set;  // key=value picture options ([output.picture] keys)
  std::string view, slab;        // the picture options view and slab, if given
  double magnification = 0;      // the picture option magnification, if above 0
};
void pictureCommand(const PictureCommandOptions& o);

struct PlotCommandOptions {
  std::vector<std::string> tables;  // timehist.dat, history.csv, ...
  std::string x;                    // column for the horizontal axis (default: the first)
  std::vector<std::string> y;       // columns to plot (default: all others)
  std::string out, title, xLabel, yLabel;
  double xScale = 1, yScale = 1;    // factors applied to the values (units, sign)
  std::vector<std::string> labels;  // legend labels, one per curve
};
void plotCommand(const PlotCommandOptions& o);

struct StrengthCommandOptions {
  std::string input;
  std::vector<std::string> set;  // key=value options of the strength search ([strength] keys)
  std::string resume;            // output folder whose search (strength/journal.txt) to continue
  bool force = false;            // even a search of another scenario or with other options
};
void strengthCommand(const StrengthCommandOptions& o);

struct ListOptions {
  std::string generator;  // one generator's parameters, defaults and ID order
};
// Prints on `root` only (every rank checks the generator's name alike).
void listCommand(const ListOptions& o, bool root);

}  // namespace pdq::cli
