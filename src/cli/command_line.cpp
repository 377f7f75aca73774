#include "cli/command_line.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <sstream>

#include "cli/guard.hpp"
#include "cli/stop.hpp"
#include "engine/error.hpp"

namespace pdq::cli {

namespace {

// Names a command line option of `app` is known by (--long, -s).
std::vector<std::string> optionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : app.get_options()) {
    for (const auto& l : opt->get_lnames()) names.push_back("--" + l);
    for (const auto& s : opt->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// "unknown option '--stpes' (did you mean '--steps'?)" for the arguments a (sub)command
// did not expect.
std::string extrasMessage(CLI::App& app) {
  CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  std::string msg;
  // The first one only: after a wrong command name the rest means nothing.
  for (const auto& arg : at->remaining()) {
    if (!msg.empty()) break;
    const bool option = arg.size() > 1 && arg[0] == '-';
    std::string name = arg.substr(0, arg.find('='));
    std::vector<std::string> commands;
    for (const CLI::App* c : at->get_subcommands({})) commands.push_back(c->get_name());
    msg += (msg.empty() ? "" : "; ") +
           (option ? "unknown option '" + name + "'" + pdq::suggestion(name, optionNames(*at))
            : commands.empty() ? "unexpected argument '" + arg + "'"
                               : "unknown command '" + arg + "'" + pdq::suggestion(arg, commands));
  }
  return (msg.empty() ? std::string("unexpected arguments") : msg) + " for 'pdq" +
         (at == &app ? "" : " " + at->get_name()) + "'";
}

}  // namespace

CommandLine parseCommandLine(int argc, const char* const* argv) {
  CommandLine c;
  auto ended = [&](int code, std::string out, std::string error) {
    c.exit = code;
    c.out = std::move(out);
    c.error = std::move(error);
    return c;
  };
  CLI::App app{
      "pdq: parallel particle dynamics (peridynamics, lattice models, molecular dynamics).\n"
      "Run alone or under mpirun -np N; see docs/tutorial.md and docs/scenario.md.",
      "pdq"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "pdq 0.1.0");
  auto help = [&](const CLI::Error& e) {
    std::ostringstream out, err;
    const int code = app.exit(e, out, err);
    return ended(code, out.str(), err.str());
  };
  std::vector<std::string>& plugins = c.plugins;
  auto addWatchdog = [&](CLI::App* cmd) {
    cmd->add_option("--watchdog", c.watchdog,
                    "under mpirun, end the job when a rank gives no sign of life for this "
                    "many seconds (stopped or lost; default 5, 0: never)")
        ->check(CLI::Range(0.0, 1e9));
  };
  auto addPlugin = [&](CLI::App* cmd) {
    cmd->add_option("--plugin", plugins,
                    "shared library with more models or generators (repeatable)")
        ->check(CLI::ExistingFile)
        ->take_all();
  };

  RunOptions& run = c.run;
  bool quiet = false, verbose = false;
  CLI::App* runCmd = app.add_subcommand("run",
                                        "run a scenario (.toml) or a folder of the "
                                        "thesis's .dat files");
  runCmd->add_option("input", run.input, "scenario file or .dat folder")->required();
  runCmd->add_option(
      "--restart", run.restart,
      "continue from this ParticleAlterAttrs.<step>.rst (with its Bonds.<step>.rst)");
  auto* resume = runCmd->add_option(
      "--resume", run.resume,
      "continue from the newest valid checkpoint in this output folder (and write there)");
  resume->excludes(runCmd->get_option("--restart"));
  runCmd
      ->add_flag("--force", run.force,
                 "resume even from a checkpoint of another scenario or time step")
      ->needs(resume);
  runCmd->add_option("--steps", run.steps, "run to this step instead of the scenario's")
      ->check(CLI::Range(0L, 1000000000000L));
  runCmd->add_option("-o,--out", run.out, "output folder instead of the scenario's")
      ->excludes(resume);
  std::string maxWall;
  runCmd->add_option("--max-wall-time", maxWall,
                     "stop with a checkpoint before this much wall time (seconds, or e.g. "
                     "90m, 2h, 1h30m); exit code 4");
  addWatchdog(runCmd);
  auto* q = runCmd->add_flag("-q,--quiet", quiet, "print only errors");
  runCmd->add_flag("-v,--verbose", verbose, "also print the setup summary and timings")
      ->excludes(q);
  addPlugin(runCmd);

  PrepOptions& prep = c.prep;
  CLI::App* prepCmd = app.add_subcommand(
      "prep", "write the particle and input files a scenario generates, in the thesis's format");
  prepCmd->add_option("scenario", prep.input, "scenario file (.toml)")->required();
  prepCmd->add_option("-o,--out", prep.out,
                      "folder for the .dat files (default: <scenario>_input)");
  addPlugin(prepCmd);

  CLI::App* postCmd = app.add_subcommand(
      "post", "pictures of the lattice and plots of histories from saved output");
  postCmd->require_subcommand(1);
  PictureCommandOptions& picture = c.picture;
  CLI::App* pictureCmd = postCmd->add_subcommand(
      "picture", "draw the lattice (damage, any attribute) from a restart file");
  pictureCmd->add_option("input", picture.input, "the scenario (or .dat folder) of the run")
      ->required();
  pictureCmd->add_option("--restart", picture.restart,
                         "ParticleAlterAttrs.<step>.rst to draw (default: the latest in the "
                         "scenario's output folder)");
  pictureCmd->add_option("-o,--out", picture.out, "picture file (.png, .svg or .pdf)");
  pictureCmd->add_option("--set", picture.set,
                         "picture option key=value, as in [output.picture] (repeatable)");
  pictureCmd->add_option("--view", picture.view,
                         "direction towards the viewer: x, y, z, -x, -y, -z or a,b,c (3D side "
                         "elevation: z; plan from below: -y)");
  pictureCmd->add_option("--slab", picture.slab,
                         "only the particles whose reference coordinate is in a range, and "
                         "the bonds between them: axis=lo:hi, e.g. z=0.05:0.11");
  pictureCmd->add_option("--magnification", picture.magnification,
                         "displacements drawn this many times larger");
  addPlugin(pictureCmd);
  PlotCommandOptions& plot = c.plot;
  CLI::App* plotCmd =
      postCmd->add_subcommand("plot", "plot columns of history.csv, timehist.dat or any table");
  plotCmd->add_option("tables", plot.tables, "text tables")->required()->check(CLI::ExistingFile);
  plotCmd->add_option("-x,--x", plot.x, "column on the horizontal axis (default: the first)");
  plotCmd->add_option("-y,--y", plot.y, "column to plot (repeatable; default: all others)");
  plotCmd->add_option("-o,--out", plot.out, "picture file (default: the table's name .png)");
  plotCmd->add_option("--title", plot.title, "plot title");
  plotCmd->add_option("--xlabel", plot.xLabel, "horizontal axis label");
  plotCmd->add_option("--ylabel", plot.yLabel, "vertical axis label");
  plotCmd->add_option("--x-scale", plot.xScale,
                      "multiply the horizontal values (e.g. -1000: m downward to mm)");
  plotCmd->add_option("--y-scale", plot.yScale, "multiply the vertical values");
  plotCmd->add_option("--label", plot.labels,
                      "legend label of each curve, in order (repeatable; default: the columns)");

  StrengthCommandOptions& strength = c.strength;
  CLI::App* strengthCmd = app.add_subcommand(
      "strength", "search the failure load of a scenario (models with a strength spec)");
  strengthCmd->add_option("input", strength.input, "scenario file or .dat folder")->required();
  strengthCmd->add_option("--set", strength.set, "search option key=value (repeatable)");
  auto* strengthResume = strengthCmd->add_option(
      "--resume", strength.resume,
      "continue the search recorded in this output folder (its strength/journal.txt), "
      "without running its finished trials again");
  strengthCmd
      ->add_flag("--force", strength.force,
                 "resume even a search of another scenario or with other options")
      ->needs(strengthResume);
  addWatchdog(strengthCmd);
  addPlugin(strengthCmd);

  InfoOptions& info = c.info;
  CLI::App* infoCmd = app.add_subcommand(
      "info", "what a scenario will do: particles, bonds, time step, memory, processor grid");
  infoCmd->add_option("input", info.input, "scenario file or .dat folder")->required();
  infoCmd->add_option("--ranks", info.ranks, "also show the processor grid for this many ranks")
      ->check(CLI::Range(1, 10000000));
  addPlugin(infoCmd);

  CLI::App* listCmd = app.add_subcommand("list", "list the models and generators");
  listCmd->add_option("--generator", c.list.generator,
                      "print one generator's parameters, their defaults and its ID order");
  addPlugin(listCmd);

  // An unknown command: say so with the nearest one, rather than CLI11's generic message.
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const CLI::App* cmd : app.get_subcommands({})) names.push_back(cmd->get_name());
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      return ended(BadCommand, "",
                   "unknown command '" + std::string(argv[1]) + "'" +
                       pdq::suggestion(argv[1], names) + "; see pdq --help");
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return help(e);
  } catch (const CLI::CallForAllHelp& e) {
    return help(e);
  } catch (const CLI::CallForVersion& e) {
    return help(e);
  } catch (const CLI::ParseError& e) {
    // Arguments nobody expected explain the error best (a misspelt option or command).
    CLI::App* at = &app;
    while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
    const bool extras = dynamic_cast<const CLI::ExtrasError*>(&e) || !at->remaining().empty();
    return ended(BadCommand, "",
                 (extras ? extrasMessage(app) : std::string(e.what())) + "; see --help");
  }
  run.verbosity = quiet ? Verbosity::Quiet : verbose ? Verbosity::Verbose : Verbosity::Normal;
  if (!maxWall.empty()) {
    try {
      run.maxWallTime = parseWallTime(maxWall);
    } catch (const std::invalid_argument& e) {
      return ended(BadCommand, "", std::string(e.what()) + "; see --help");
    }
  }
  if (prep.out.empty() && !prep.input.empty())
    prep.out = std::filesystem::path(prep.input).stem().string() + "_input";
  using C = CommandLine::Command;
  c.command = runCmd->parsed()        ? C::Run
              : prepCmd->parsed()     ? C::Prep
              : pictureCmd->parsed()  ? C::Picture
              : plotCmd->parsed()     ? C::Plot
              : strengthCmd->parsed() ? C::Strength
              : infoCmd->parsed()     ? C::Info
                                      : C::List;
  return c;
}

}  // namespace pdq::cli
