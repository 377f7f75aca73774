#pragma once
// The pdq command line: `pdq run|prep|post picture|post plot|strength|info|list ...` read
// into the options of one command, or into an early end (help, version, a bad command
// line) with what to print. Reads no input file and needs no MPI, so every rank parses
// the same line alike.
#include <string>
#include <vector>

#include "cli/commands.hpp"

namespace pdq::cli {

struct CommandLine {
  enum class Command { Run, Prep, Picture, Plot, Strength, Info, List };
  Command command = Command::List;
  RunOptions run;
  PrepOptions prep;
  PictureCommandOptions picture;
  PlotCommandOptions plot;
  StrengthCommandOptions strength;
  InfoOptions info;
  ListOptions list;
  std::vector<std::string> plugins;  // --plugin libraries to load first
  double watchdog = 5;  // seconds a rank may give no sign of life (cli/watchdog.hpp); 0: off
  // exit >= 0: pdq ends with this code, printing `out` (help, version) on standard output
  // and `error` as an error, and runs no command.
  int exit = -1;
  std::string out, error;
};

CommandLine parseCommandLine(int argc, const char* const* argv);

}  // namespace pdq::cli
