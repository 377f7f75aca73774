#include "scenario/scenario.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>

#include "engine/error.hpp"
#include "engine/memory.hpp"
#include "io/thesis_input.hpp"
#include "io/vtu_output.hpp"
#include "post/picture_output.hpp"
#include "prep/generator.hpp"
#include "scenario/assignment.hpp"

namespace pdq {

namespace fs = std::filesystem;

namespace {

int lineOf(const toml::node& n) { return static_cast<int>(n.source().begin.line); }

// A scalar as Params text: numbers exactly (%.17g round-trips), words as written.
std::string scalarText(const toml::node& v, const std::string& file, const std::string& key) {
  if (auto s = v.as_string()) return s->get();
  if (auto i = v.as_integer()) return std::to_string(i->get());
  if (auto d = v.as_floating_point()) return numberText(d->get());
  if (auto b = v.as_boolean()) return b->get() ? "true" : "false";
  throw InputError(file, lineOf(v), "'" + key + "' must be a number, a word or true/false");
}

// The keys of one table as Params (arrays become space-separated items). Sub-tables and
// arrays of tables are entered with empty text, so that one nobody reads is reported
// like any unknown key.
// `skip`: keys read by the caller itself.
Params tableParams(const toml::table& t, const std::string& file, const std::string& owner,
                   std::initializer_list<const char*> skip = {}) {
  Params p(owner);
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    if (std::find(skip.begin(), skip.end(), k) != skip.end()) continue;
    std::string text;
    if (node.is_table()) {
      text = "";
    } else if (auto arr = node.as_array()) {
      if (arr->is_array_of_tables() && !arr->empty()) {
        text = "";
      } else {
        for (auto&& item : *arr) {
          if (item.is_array() || item.is_table())
            throw InputError(file, lineOf(item), "'" + k + "' must be a flat list of values");
          if (!text.empty()) text += ' ';
          text += scalarText(item, file, k);
        }
      }
    } else {
      text = scalarText(node, file, k);
    }
    p.set(k, text, file, lineOf(node));
  }
  return p;
}

const toml::table* subTable(const toml::table& t, const char* key, const std::string& file) {
  const toml::node* n = t.get(key);
  if (!n) return nullptr;
  if (!n->is_table())
    throw InputError(file, lineOf(*n), std::string("'") + key + "' must be a table");
  return n->as_table();
}

std::array<bool, 3> flags3(const Params& p, const std::string& key, const std::string& file) {
  const auto v = p.raw(key);
  std::array<bool, 3> out{};
  std::vector<std::string> words;
  std::string w;
  for (char c : v->text + " ")
    if (c == ' ') {
      if (!w.empty()) words.push_back(w);
      w.clear();
    } else {
      w += c;
    }
  if (words.size() != 3)
    throw InputError(file, v->line, key + " needs 3 flags, e.g. [true, false, false]");
  for (int a = 0; a < 3; ++a) {
    if (words[a] == "true" || words[a] == "1")
      out[a] = true;
    else if (words[a] != "false" && words[a] != "0")
      throw InputError(file, v->line, key + ": '" + words[a] + "' is not true or false");
  }
  return out;
}

std::array<double, 3> numbers3(const Params& p, const std::string& key, const std::string& file) {
  const auto v = p.numbers(key);
  if (v.size() != 3) throw InputError(file, p.raw(key)->line, key + " needs 3 numbers");
  return {v[0], v[1], v[2]};
}

void readModel(const toml::table& root, const std::string& file, Scenario& sc) {
  Problem& pb = sc.problem;
  const toml::node* m = root.get("model");
  if (!m) throw InputError(file, 0, "missing the model: add a [model] table with name = \"...\"");
  int nameLine = lineOf(*m);
  if (m->is_string()) {
    pb.modelName = m->as_string()->get();  // `model = "name"`: all parameters at their defaults
    sc.modelParams = Params("model '" + pb.modelName + "' ([model])");
  } else if (const toml::table* t = m->as_table()) {
    const toml::node* name = t->get("name");
    if (!name || !name->is_string())
      throw InputError(file, lineOf(*m), "[model] needs name = \"...\" (the model to run)");
    pb.modelName = name->as_string()->get();
    nameLine = lineOf(*name);
    sc.modelParams = tableParams(*t, file, "model '" + pb.modelName + "' ([model])", {"name"});
  } else {
    throw InputError(file, nameLine, "'model' must be a table ([model] with name = \"...\")");
  }
  pb.model = ModelRegistry::create(pb.modelName, sc.modelParams, file, nameLine);
}

// The particle records of a particle file, counted without reading them into memory.
double countRecords(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  double n = 0;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first != std::string::npos && line[first] != '#') ++n;
  }
  return n;
}

Generated readParticles(const toml::table& root, const std::string& file, Scenario& sc,
                        bool estimateOnly) {
  Problem& pb = sc.problem;
  const toml::table* t = subTable(root, "particles", file);
  if (!t)
    throw InputError(file, 0,
                     "missing [particles]: give fixed = \"...\" and alter = \"...\" files, or a "
                     "generator = \"...\"");
  const Schema schema = pb.model->schema();
  Params p = tableParams(*t, file, "[particles]");
  Generated g;
  const bool files = p.has("fixed") || p.has("alter");
  if (p.has("generator")) {
    const auto name = p.raw("generator");
    if (files)
      throw InputError(file, name->line, "give either a generator or fixed/alter files, not both");
    p.accept("set");
    const auto& gen = GeneratorRegistry::get(name->text, file, name->line);
    Params gp =
        tableParams(*t, file, "generator '" + name->text + "' ([particles])", {"generator", "set"});
    // The generator's own errors name the generator's line.
    gp.set("generator", name->text, file, name->line);
    gp.accept("generator");
    if (estimateOnly) {
      sc.generator = name->text;
      pb.run.particlesLine = name->line;
      for (const auto& [known, what] : EstimateRegistry::list())
        if (known == name->text) sc.estimate = EstimateRegistry::get(known)(gp, sc.modelParams);
      return g;
    }
    try {
      g = gen(gp, schema, sc.modelParams);
    } catch (const MemoryError& e) {
      throw InputError(file, name->line, "generator '" + name->text + "': " + e.what());
    }
    gp.checkAllUsed();
    sc.generator = name->text;
    pb.run.particlesLine = name->line;
    sc.generatorParams = gp;
    if (g.particles.nFixed != schema.nFixed() || g.particles.nAlter != schema.nAlter())
      throw InputError(file, name->line,
                       "generator '" + name->text + "' made particles of another model's widths");
    if (g.particles.size() == 0)
      throw InputError(file, name->line, "generator '" + name->text + "' made no particles");
  } else if (files) {
    const fs::path base = fs::path(file).parent_path();
    auto path = [&](const char* key) {
      if (!p.has(key))
        throw InputError(file, lineOf(*t),
                         std::string("[particles] needs both fixed and alter ") + "files (" + key +
                             " is missing)");
      const auto v = p.raw(key);
      const fs::path f = fs::path(v->text).is_absolute() ? fs::path(v->text) : base / v->text;
      if (!fs::is_regular_file(f))
        throw InputError(file, v->line, "cannot read " + f.string() + ": no such file");
      return f.string();
    };
    const std::string fixed = path("fixed"), alter = path("alter");
    p.accept("set");
    p.checkAllUsed();
    if (estimateOnly) {
      sc.estimate.emplace().particles = countRecords(fixed);
      return g;
    }
    g.particles = readParticleFiles(fixed, alter, schema);
    pb.run.particlesLine = p.raw("fixed")->line;
  } else {
    p.accept("fixed");
    p.accept("alter");
    p.accept("generator");
    p.accept("set");
    p.checkAllUsed();
    throw InputError(file, lineOf(*t),
                     "[particles] needs fixed = \"...\" and alter = \"...\" files, or a generator");
  }
  // [[particles.set]]
  if (const toml::node* s = t->get("set")) {
    const toml::array* arr = s->as_array();
    if (!arr || !arr->is_array_of_tables())
      throw InputError(file, lineOf(*s), "'set' must be a list of tables: [[particles.set]]");
    std::vector<Assignment> entries;
    for (auto&& e : *arr)
      entries.push_back(
          readAssignment(tableParams(*e.as_table(), file, "[[particles.set]]"), file, lineOf(e)));
    const auto counts = applyAssignments(g.particles, schema, entries);
    for (std::size_t k = 0; k < entries.size(); ++k)
      sc.setCounts.push_back({entries[k].line, entries[k].attribute, counts[k]});
  }
  return g;
}

void readDecomposition(const toml::table& root, const std::string& file, const Generated& g,
                       Problem& pb) {
  RunConfig& run = pb.run;
  const toml::table* t = subTable(root, "decomposition", file);
  Params p = t ? tableParams(*t, file, "[decomposition]") : Params("[decomposition]");
  if (p.has("procs")) {
    const auto v = p.numbers("procs");
    const int at = p.raw("procs")->line;
    if (v.size() != 3)
      throw InputError(file, at, "procs needs 3 numbers (processors along X, Y, Z; 0: automatic)");
    for (int a = 0; a < 3; ++a) {
      if (v[a] < 0 || v[a] != std::floor(v[a]) || v[a] > 1e6)
        throw InputError(file, at, "processor counts must be whole numbers >= 0");
      run.procs[a] = static_cast<int>(v[a]);
    }
  }
  run.minCellSize = p.number("min_cell_size", 0.0, 0.0, 1e300);
  const double horizon = pb.model->horizon();
  if (run.minCellSize > 0 && run.minCellSize < horizon) {
    throw InputError(file, p.raw("min_cell_size")->line,
                     "min_cell_size " + numberText(run.minCellSize) +
                         " is below the model's horizon " + numberText(horizon) +
                         "; neighbours would be missed");
  }
  run.margin = p.number("margin", -1.0, 0.0, 1e300);
  run.dim = static_cast<int>(p.number("dimension", 0.0, 0.0, 3.0));
  if (p.has("dimension") && p.integer("dimension") != run.dim)
    throw InputError(file, p.raw("dimension")->line, "dimension must be 1, 2 or 3");
  if (p.has("periodic")) run.periodic = flags3(p, "periodic", file);
  const bool anyPeriodic = run.periodic[0] || run.periodic[1] || run.periodic[2];
  if (p.has("box_lo") || p.has("box_hi")) {
    if (!p.has("box_lo") || !p.has("box_hi"))
      throw InputError(file, p.raw(p.has("box_lo") ? "box_lo" : "box_hi")->line,
                       "give both box_lo and box_hi");
    run.boxLo = numbers3(p, "box_lo", file);
    run.boxHi = numbers3(p, "box_hi", file);
  } else if (g.boxLo && g.boxHi) {
    run.boxLo = *g.boxLo;
    run.boxHi = *g.boxHi;
  } else if (anyPeriodic) {
    throw InputError(file, p.raw("periodic")->line,
                     "periodic axes need a box: give box_lo and box_hi");
  }
  for (int a = 0; a < 3; ++a)
    if (run.periodic[a] && !(run.boxHi[a] > run.boxLo[a]))
      throw InputError(file, p.raw("periodic")->line,
                       std::string("the box along periodic axis ") + "XYZ"[a] + " needs hi > lo");
  p.checkAllUsed();
}

void readOutput(const toml::table& root, const std::string& file, Problem& pb) {
  OutputSettings& out = pb.output;
  const toml::table* t = subTable(root, "output", file);
  Params p = t ? tableParams(*t, file, "[output]") : Params("[output]");
  pb.run.outDir = p.text("dir", fs::path(file).stem().string() + "_out");
  if (pb.run.outDir.empty()) throw InputError(file, p.raw("dir")->line, "dir must not be empty");
  out.restartEvery = p.integer("restart_every", 0);
  out.finalRestart = p.flag("final_restart", true);
  out.historyEvery = p.integer("history_every", 0);
  out.globalsEvery = p.integer("globals_every", 0);
  out.checkpointEvery = p.integer("checkpoint_every", 0);
  out.checkpointMinutes = p.number("checkpoint_minutes", 0.0);
  out.checkpointsKept = p.integer("checkpoints_kept", 2);
  for (const char* k : {"restart_every", "history_every", "globals_every", "checkpoint_every"})
    if (p.has(k) && p.integer(k) < 0)
      throw InputError(file, p.raw(k)->line, std::string(k) + " must be >= 0 (0: never)");
  if (!(out.checkpointMinutes >= 0))
    throw InputError(file, p.raw("checkpoint_minutes")->line,
                     "checkpoint_minutes must be >= 0 (0: never)");
  if (out.checkpointsKept < 1)
    throw InputError(file, p.raw("checkpoints_kept")->line, "checkpoints_kept must be >= 1");
  if (p.has("history_ids")) {
    std::set<Gid> known(pb.particles.gid.begin(), pb.particles.gid.end());
    const int at = p.raw("history_ids")->line;
    for (double v : p.numbers("history_ids")) {
      const Gid id = static_cast<Gid>(v);
      if (v != static_cast<double>(id) || !known.count(id))
        throw InputError(file, at, "history_ids: " + numberText(v) + " is not a particle's ID");
      out.historyIds.push_back(id);
    }
  }
  if (out.historyEvery > 0 && out.historyIds.empty())
    throw InputError(file, p.raw("history_every")->line,
                     "history_every needs history_ids (the particles to follow)");
  if (t) {
    if (const toml::table* v = subTable(*t, "paraview", file)) {
      p.accept("paraview");
      out.paraview = std::make_unique<Params>(tableParams(*v, file, "[output.paraview]"));
      vtuOptions(*out.paraview);
      out.paraview->checkAllUsed();
    }
    if (const toml::table* v = subTable(*t, "picture", file)) {
      p.accept("picture");
      out.picture = std::make_unique<Params>(tableParams(*v, file, "[output.picture]"));
      const post::PictureOptions o = post::pictureOptions(*out.picture);
      out.picture->checkAllUsed();
      const Schema schema = pb.model->schema();
      std::vector<std::string> bondNames{"broken"};  // the engine's flag, then the model's
      bondNames.insert(bondNames.end(), schema.bond.begin(), schema.bond.end());
      post::checkRequest(o.request, post::quantityNames(schema, *pb.model), bondNames);
    }
  }
  p.checkAllUsed();
}

}  // namespace

Scenario readScenario(const std::string& path, bool estimateOnly) {
  if (!fs::is_regular_file(path))
    throw InputError(path, 0, "cannot read the scenario: no such file");
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw InputError(path, static_cast<int>(e.source().begin.line),
                     "not valid TOML: " + std::string(e.description()));
  }
  Scenario sc;
  Problem& pb = sc.problem;
  pb.source = path;
  pb.run.source = path;
  Params top = tableParams(root, path, "the scenario");
  for (const char* k :
       {"model", "particles", "decomposition", "output", "strength", "loading", "solver"})
    top.accept(k);
  top.text("description", "");
  const toml::table* lt = subTable(root, "loading", path);
  const Params loading = lt ? tableParams(*lt, path, "[loading]") : Params("[loading]");
  pb.run.loading = readLoading(loading);
  loading.checkAllUsed();
  const toml::table* st = subTable(root, "solver", path);
  const Params solver = st ? tableParams(*st, path, "[solver]", {"control"}) : Params("[solver]");
  pb.run.solver = readSolver(solver, "kind");
  solver.checkAllUsed();
  // [solver.control]: displacement control of the particles it selects (resolved to IDs
  // once the particles exist).
  const toml::table* ct = st ? subTable(*st, "control", path) : nullptr;
  std::optional<Selection> controlled;
  if (ct) {
    if (!pb.run.solver.quasiStatic)
      throw InputError(path, lineOf(*ct),
                       "[solver.control] is the quasi-static solver's displacement control; set "
                       "kind = \"quasi_static\"");
    const Params c = tableParams(*ct, path, "[solver.control]");
    pb.run.solver.control = readControl(c, "");
    if (!pb.run.solver.control.active())
      throw InputError(path, lineOf(*ct),
                       "[solver.control] needs axis (x, y or z) and displacement (the peak "
                       "displacement along it)");
    controlled = readSelection(c, path);
    c.checkAllUsed();
  }
  if (pb.run.solver.quasiStatic) {
    checkStaticLoading(pb.run.solver, loading);
    if (top.has("steps"))
      throw InputError(path, top.raw("steps")->line,
                       "the quasi-static solver's run is its [solver] load_steps; remove steps");
    pb.run.steps = pb.run.solver.loadSteps;
    top.checkAllUsed();
  } else if (!top.has("steps") && !loading.has("hold_time"))
    throw InputError(path, 0,
                     "missing steps = N (the number of time steps; or [loading] hold_time)");
  if (top.has("steps") && loading.has("hold_time"))
    throw InputError(path, top.raw("steps")->line,
                     "give the run's length as steps = N or as [loading] hold_time, not both");
  if (!pb.run.solver.quasiStatic) {
    pb.run.steps = top.integer("steps", -1);
    if (top.has("steps") && pb.run.steps < 0)
      throw InputError(path, top.raw("steps")->line, "steps must be >= 0");
    top.checkAllUsed();
  }

  readModel(root, path, sc);
  Generated g = readParticles(root, path, sc, estimateOnly);
  if (estimateOnly) return sc;
  pb.particles = std::move(g.particles);
  if (controlled) {
    pb.run.solver.control.ids = controlled->selected(pb.particles);
    if (pb.run.solver.control.ids.empty())
      throw InputError(path, pb.run.solver.control.line,
                       "[solver.control] selects no particle (check its x, y, z ranges and ids "
                       "against the particles' reference positions)");
  }
  readDecomposition(root, path, g, pb);
  readOutput(root, path, pb);
  if (const toml::table* t = subTable(root, "strength", path)) {
    sc.strength = tableParams(*t, path, "[strength]", {"model"});
    if (const toml::table* m = subTable(*t, "model", path))
      sc.strengthModel = tableParams(*m, path, "[strength.model]");
  }
  return sc;
}

Scenario loadScenario(const std::string& path) {
  if (fs::is_directory(path)) {
    Scenario sc;
    sc.problem = readThesisInput(path);
    return sc;
  }
  return readScenario(path);
}

}  // namespace pdq
