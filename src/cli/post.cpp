// pdq post: pictures of the lattice from a restart file, and plots of time histories.
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string_view>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "engine/atomic_file.hpp"
#include "engine/error.hpp"
#include "io/restart.hpp"
#include "io/standard_outputs.hpp"
#include "post/line_plot.hpp"
#include "post/picture_output.hpp"
#include "post/snapshot.hpp"
#include "post/table.hpp"
#include "scenario/scenario.hpp"

namespace pdq::cli {

namespace fs = std::filesystem;

namespace {

// The restart file of the highest step in `dir`.
std::string latestRestart(const std::string& dir, const std::string& input) {
  // ParticleAlterAttrs.<digits>.rst, matched by hand (<regex> is slow to compile).
  constexpr std::string_view head = "ParticleAlterAttrs.", tail = ".rst";
  std::string best;
  long bestStep = -1;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string f = e.path().filename().string();
    if (f.size() <= head.size() + tail.size() || !f.starts_with(head) || !f.ends_with(tail))
      continue;
    const std::string digits = f.substr(head.size(), f.size() - head.size() - tail.size());
    if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      continue;
    // A step beyond any run's (more digits than a long holds) is no restart file of pdq's.
    long step = -1;
    const auto [end, err] = std::from_chars(digits.data(), digits.data() + digits.size(), step);
    if (err == std::errc() && step > bestStep) {
      bestStep = step;
      best = e.path().string();
    }
  }
  if (best.empty())
    throw InputError(input, 0,
                     "no restart file (ParticleAlterAttrs.<step>.rst) in " + dir +
                         "; run the scenario first or give --restart");
  return best;
}

}  // namespace

void pictureCommand(const PictureCommandOptions& o) {
  Comm comm;
  Scenario sc = loadScenario(o.input);
  Problem& pb = sc.problem;
  const std::string restart = o.restart.empty() ? latestRestart(pb.run.outDir, o.input) : o.restart;
  // Any step may be drawn, also from a run longer than the scenario's (a strength trial).
  pb.run.steps = std::numeric_limits<long>::max();
  pb.restart = readRestart(restart, pb);
  // The picture options: the scenario's [output.picture] table, then --set items.
  Params table = pb.output.picture ? *pb.output.picture : Params("picture options");
  setFromCommandLine(table, o.set);
  if (!o.view.empty()) table.set("view", o.view, "--view", 0);
  if (!o.slab.empty()) table.set("slab", o.slab, "--slab", 0);
  if (o.magnification > 0)
    table.set("magnification", numberText(o.magnification), "--magnification", 0);
  post::PictureOptions opt = post::pictureOptions(table);
  table.checkAllUsed();
  const Schema schema = pb.model->schema();
  std::vector<std::string> bondNames{"broken"};  // the engine's flag, then the model's
  bondNames.insert(bondNames.end(), schema.bond.begin(), schema.bond.end());
  post::checkRequest(opt.request, post::quantityNames(schema, *pb.model), bondNames);
  // Set up (bonds, fields) at the restart's step without stepping, so the picture is
  // the one the run would have drawn at that step.
  const std::string outDir = pb.run.outDir;
  pb.run.steps = pb.run.firstStep;
  // A quasi-static run that cut back has more load steps than `load_steps`: draw any.
  pb.run.solver.loadSteps = std::max(pb.run.solver.loadSteps, pb.run.steps);
  pb.run.outDir.assign(1, '.');
  pb.output = {.finalRestart = false};
  const auto simulation = makeSimulation(std::move(pb), comm);
  Simulation& sim = *simulation;
  sim.setup();
  const post::Snapshot snap = post::gatherSnapshot(sim.context(), sim.model(), comm, sim.step());
  if (comm.root()) {
    std::string path = o.out;
    if (path.empty()) {
      createFolder(outDir);
      path = outDir + "/" + post::PictureOutput::fileName(opt, sim.step());
    }
    post::PictureRequest request = opt.request;
    if (request.style.title.empty())  // as the run titles its pictures
      request.style.title = fmt::format("step {}, t = {:.4g}", snap.step, snap.time);
    post::renderSnapshot(snap, request, path);
    std::printf("wrote %s (step %ld, %zu particles)\n", path.c_str(), sim.step(), snap.particles());
  }
  comm.barrier();
}

void plotCommand(const PlotCommandOptions& o) {
  Comm comm;
  std::vector<post::Table> tables;
  for (const auto& t : o.tables) tables.push_back(post::readTable(t));
  std::vector<post::Series> series;
  std::string xName;
  for (const auto& t : tables) {
    const std::string x = o.x.empty() ? t.names.at(0) : o.x;
    xName = x;
    std::vector<double> xs = t.column(x);
    for (double& v : xs) v *= o.xScale;
    std::vector<std::string> ys = o.y;
    if (ys.empty())
      for (const auto& n : t.names)
        if (n != x) ys.push_back(n);
    for (const auto& y : ys) {
      const std::string label =
          tables.size() > 1 ? fs::path(t.source).filename().string() + ": " + y : y;
      std::vector<double> values = t.column(y);
      for (double& v : values) v *= o.yScale;
      series.push_back({label, xs, values});
    }
  }
  if (!o.labels.empty()) {
    if (o.labels.size() != series.size())
      throw InputError(
          "command line", 0,
          fmt::format("--label given {} time(s) for {} curve(s)", o.labels.size(), series.size()));
    for (std::size_t k = 0; k < series.size(); ++k) series[k].name = o.labels[k];
  }
  post::PlotStyle style;
  style.title = o.title.empty() ? fs::path(o.tables[0]).filename().string() : o.title;
  style.xLabel = o.xLabel.empty() ? xName : o.xLabel;
  style.yLabel = o.yLabel.empty() && series.size() == 1 ? series[0].name : o.yLabel;
  const std::string path =
      o.out.empty() ? fs::path(o.tables[0]).replace_extension(".png").string() : o.out;
  if (comm.root()) {
    post::plotLines(series, style, path);
    std::printf("wrote %s (%zu curve%s)\n", path.c_str(), series.size(),
                series.size() == 1 ? "" : "s");
  }
  comm.barrier();
}

}  // namespace pdq::cli
