#include "io/thesis_input.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"
#include "io/text_table.hpp"

namespace pdq {

namespace {

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

// `key value...` lines into Params, keeping file and line for every value.
void readKeyValues(const std::string& path, const std::vector<std::pair<int, std::string>>& lines,
                   std::size_t first, Params& into) {
  for (std::size_t k = first; k < lines.size(); ++k) {
    std::istringstream in(lines[k].second);
    std::string key, word, rest;
    in >> key;
    while (in >> word) rest += (rest.empty() ? "" : " ") + word;
    if (rest.empty()) throw InputError(path, lines[k].first, "'" + key + "' has no value");
    if (into.raw(key)) throw InputError(path, lines[k].first, "'" + key + "' is given twice");
    into.set(key, rest, path, lines[k].first);
  }
}

Gid toGid(double v, const std::string& path, int line) {
  if (v != static_cast<double>(static_cast<Gid>(v)) || v < 0)
    throw InputError(path, line, "the global ID must be a non-negative whole number");
  return static_cast<Gid>(v);
}

}  // namespace

ParticleSet readParticleFiles(const std::string& fixedPath, const std::string& alterPath,
                              const Schema& schema) {
  ParticleSet ps;
  ps.nFixed = schema.nFixed();
  ps.nAlter = schema.nAlter();
  const auto fixed = readNumberTable(fixedPath, 1 + ps.nFixed, "id " + join(schema.fixed));
  const auto alter = readNumberTable(alterPath, 1 + ps.nAlter, "id " + join(schema.alter));
  if (fixed.empty()) throw InputError(fixedPath, 0, "no particle records");
  std::unordered_map<Gid, std::size_t> index;
  index.reserve(fixed.size());
  ps.gid.reserve(fixed.size());
  ps.fixed.reserve(fixed.size() * ps.nFixed);
  for (const auto& r : fixed) {
    const Gid id = toGid(r.values[0], fixedPath, r.line);
    if (!index.emplace(id, ps.gid.size()).second)
      throw InputError(fixedPath, r.line, "duplicate global ID " + std::to_string(id));
    ps.gid.push_back(id);
    ps.fixed.insert(ps.fixed.end(), r.values.begin() + 1, r.values.end());
  }
  ps.alter.assign(ps.gid.size() * ps.nAlter, 0.0);
  std::vector<char> seen(ps.gid.size(), 0);
  for (const auto& r : alter) {
    const Gid id = toGid(r.values[0], alterPath, r.line);
    auto it = index.find(id);
    if (it == index.end())
      throw InputError(alterPath, r.line,
                       "global ID " + std::to_string(id) + " is not in " + fixedPath);
    if (seen[it->second]++)
      throw InputError(alterPath, r.line, "duplicate global ID " + std::to_string(id));
    std::copy(r.values.begin() + 1, r.values.end(), ps.alterRow(it->second));
  }
  for (std::size_t k = 0; k < seen.size(); ++k)
    if (!seen[k])
      throw InputError(
          alterPath, 0,
          "global ID " + std::to_string(ps.gid[k]) + " of " + fixedPath + " is missing");
  return ps;
}

Problem readThesisInput(const std::string& dir) {
  Problem pb;
  const std::string input = dir + "/pdQInput.dat", user = dir + "/pdQUserInput.dat";
  pb.source = input;
  // pdQInput.dat: five numbers, then engine settings.
  const auto lines = readLines(input);
  std::vector<double> head;
  std::size_t k = 0;
  int lastLine = 0, cellLine = 0;
  for (; k < lines.size() && head.size() < 5; ++k) {
    std::istringstream in(lines[k].second);
    std::string tok;
    while (in >> tok) {
      double v;
      std::istringstream num(tok);
      if (!(num >> v) || !num.eof())
        throw InputError(input, lines[k].first,
                         "'" + tok +
                             "' is not a number (expected nPX nPY nPZ, minimum cell size, "
                             "number of time steps)");
      head.push_back(v);
      if (head.size() == 4) cellLine = lines[k].first;
    }
    lastLine = lines[k].first;
  }
  if (head.size() != 5)
    throw InputError(input, lastLine,
                     "expected five numbers: nPX nPY nPZ, minimum cell size, number of time steps");
  for (int a = 0; a < 3; ++a) {
    if (head[a] < 0 || head[a] != static_cast<int>(head[a]))
      throw InputError(input, lines[0].first, "processor counts must be whole numbers >= 0");
    pb.run.procs[a] = static_cast<int>(head[a]);
  }
  pb.run.minCellSize = head[3];
  if (!(head[3] > 0)) throw InputError(input, lastLine, "the minimum cell size must be positive");
  if (head[4] < -1 || head[4] != static_cast<long>(head[4]))
    throw InputError(input, lastLine,
                     "the number of time steps must be a whole number >= 0 (or -1 with hold_time)");
  pb.run.steps = static_cast<long>(head[4]);
  pb.run.source = input;
  Params engine("pdQInput.dat");
  readKeyValues(input, lines, k, engine);
  pb.run.margin = engine.number("margin", -1);
  const long dim = engine.integer("dimension", 0);
  if (dim < 0 || dim > 3)
    throw InputError(
        input, engine.raw("dimension")->line,
        "dimension must be 1, 2 or 3 (or 0: from the particles), not " + std::to_string(dim));
  pb.run.dim = static_cast<int>(dim);
  if (engine.has("periodic")) {
    const auto f = engine.numbers("periodic");
    if (f.size() != 3)
      throw InputError(input, engine.raw("periodic")->line, "periodic needs 3 flags (0/1)");
    for (int a = 0; a < 3; ++a) pb.run.periodic[a] = f[a] != 0;
    const auto lo = engine.numbers("box_lo"), hi = engine.numbers("box_hi");
    if (lo.size() != 3 || hi.size() != 3)
      throw InputError(input, engine.raw("periodic")->line,
                       "box_lo and box_hi need 3 numbers each");
    for (int a = 0; a < 3; ++a) pb.run.boxLo[a] = lo[a], pb.run.boxHi[a] = hi[a];
  }
  pb.output.restartEvery = engine.integer("restart_every", 0);
  pb.output.historyEvery = engine.integer("history_every", 0);
  const int idsLine = engine.has("history_ids") ? engine.raw("history_ids")->line : 0;
  if (engine.has("history_ids"))
    for (double v : engine.numbers("history_ids")) {
      if (!(v >= 0 && v <= 9.0e15) || v != static_cast<double>(static_cast<Gid>(v)))
        throw InputError(input, idsLine,
                         "history_ids: " + numberText(v) +
                             " is not a particle's ID (a whole "
                             "number >= 0)");
      pb.output.historyIds.push_back(static_cast<Gid>(v));
    }
  pb.output.globalsEvery = engine.integer("globals_every", 0);
  pb.run.loading = readLoading(engine);
  pb.run.solver = readSolver(engine, "solver");
  if (pb.run.solver.quasiStatic) {
    checkStaticLoading(pb.run.solver, engine);
    if (pb.run.steps != pb.run.solver.loadSteps)
      throw InputError(input, lastLine,
                       "with the quasi-static solver the number of steps is the number of "
                       "load steps: give " +
                           std::to_string(pb.run.solver.loadSteps) + " (load_steps)");
  } else {
    if (pb.run.steps < 0 && !engine.has("hold_time"))
      throw InputError(input, lastLine, "-1 time steps needs hold_time (the run's length)");
    if (pb.run.steps >= 0 && engine.has("hold_time"))
      throw InputError(input, engine.raw("hold_time")->line,
                       "give the run's length as the number of steps or as hold_time (with "
                       "steps -1), not both");
  }
  engine.checkAllUsed();

  // pdQUserInput.dat: the model and its parameters.
  const auto ulines = readLines(user);
  Params modelParams("the model in pdQUserInput.dat");
  readKeyValues(user, ulines, 0, modelParams);
  const auto name = modelParams.raw("model");
  if (!name) throw InputError(user, 0, "missing 'model NAME' line");
  pb.modelName = name->text;
  pb.model = ModelRegistry::create(pb.modelName, modelParams, user, name->line);
  if (pb.run.minCellSize < pb.model->horizon())
    throw InputError(input, cellLine,
                     "the minimum cell size " + numberText(pb.run.minCellSize) +
                         " is below the model's horizon " + numberText(pb.model->horizon()) +
                         "; neighbours would be missed");
  pb.particles = readParticleFiles(dir + "/ParticleFixedAttrs.dat", dir + "/ParticleAlterAttrs.dat",
                                   pb.model->schema());
  if (!pb.run.solver.control.ids.empty()) {
    const std::unordered_set<Gid> ids(pb.particles.gid.begin(), pb.particles.gid.end());
    for (Gid g : pb.run.solver.control.ids)
      if (!ids.count(g))
        throw InputError(input, engine.raw("control_ids")->line,
                         "control_ids: " + std::to_string(g) + " is not a particle's ID");
  }
  if (!pb.output.historyIds.empty()) {
    const std::unordered_set<Gid> ids(pb.particles.gid.begin(), pb.particles.gid.end());
    for (Gid g : pb.output.historyIds)
      if (!ids.count(g))
        throw InputError(input, idsLine,
                         "history_ids: " + std::to_string(g) + " is not a particle's ID");
  }
  return pb;
}

void writeParticleFiles(const std::string& dir, const ParticleSet& ps, const Schema& schema) {
  createFolder(dir);
  for (int which = 0; which < 2; ++which) {
    const bool fixed = which == 0;
    AtomicFile f(dir + (fixed ? "/ParticleFixedAttrs.dat" : "/ParticleAlterAttrs.dat"));
    auto& out = f.stream();
    out << "# id " << join(fixed ? schema.fixed : schema.alter) << "\n";
    const int w = fixed ? ps.nFixed : ps.nAlter;
    std::string line;
    for (std::size_t k = 0; k < ps.size(); ++k) {
      line = std::to_string(ps.gid[k]);
      const double* row = fixed ? ps.fixedRow(k) : ps.alterRow(k);
      for (int c = 0; c < w; ++c) (line += ' ') += numberText(row[c]);
      out << line << "\n";
    }
    f.commit();
  }
}

void writeThesisInput(const std::string& dir, const Problem& pb, const Params& modelParams) {
  createFolder(dir);
  // pdQInput.dat always states the cell size: a problem's default is the model's own.
  const double cellSize = pb.run.minCellSize > 0 ? pb.run.minCellSize : pb.model->minCellSize();
  std::ostringstream in;
  in << pb.run.procs[0] << " " << pb.run.procs[1] << " " << pb.run.procs[2]
     << "   # nPX nPY nPZ (0: automatic)\n"
     << numberText(cellSize) << "   # minimum cell size\n"
     << pb.run.steps << "   # number of time steps\n";
  if (pb.run.margin >= 0) in << "margin " << numberText(pb.run.margin) << "\n";
  if (pb.run.dim) in << "dimension " << pb.run.dim << "\n";
  if (pb.run.periodic[0] || pb.run.periodic[1] || pb.run.periodic[2]) {
    in << "periodic " << pb.run.periodic[0] << " " << pb.run.periodic[1] << " "
       << pb.run.periodic[2] << "\nbox_lo";
    for (double v : pb.run.boxLo) in << " " << numberText(v);
    in << "\nbox_hi";
    for (double v : pb.run.boxHi) in << " " << numberText(v);
    in << "\n";
  }
  if (pb.output.restartEvery) in << "restart_every " << pb.output.restartEvery << "\n";
  if (pb.output.historyEvery) {
    in << "history_every " << pb.output.historyEvery << "\nhistory_ids";
    for (Gid g : pb.output.historyIds) in << " " << g;
    in << "\n";
  }
  if (pb.output.globalsEvery) in << "globals_every " << pb.output.globalsEvery << "\n";
  in << writeLoading(pb.run.loading) << writeSolver(pb.run.solver);
  writeFileAtomically(dir + "/pdQInput.dat", in.str());
  std::ostringstream user;
  user << "model " << pb.modelName << "\n";
  for (const auto& key : modelParams.keys())
    if (key != "model") user << key << " " << modelParams.raw(key)->text << "\n";
  writeFileAtomically(dir + "/pdQUserInput.dat", user.str());
  writeParticleFiles(dir, pb.particles, pb.model->schema());
}

}  // namespace pdq
