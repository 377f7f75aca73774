// The conformance suite: every model of ModelRegistry::list(), and the example plugin,
// must
//   (a) give forces (and moments) that are minus the gradient of its potential energy (the
//       global "potential"), by central differences on a small perturbed lattice;
//   (b) give bitwise the same run on 1 and 3 ranks, with 1 and 2 threads;
//   (c) continue bitwise from a restart at a random step;
//   (d) declare its attributes, fields and globals under distinct names, by which they are
//       found and evaluated.
// A model is tested by registering it and describing a small problem (or several) for it
// below; a model without one fails the suite. Rotations are those the model's motion()
// declares: planar (an angle) or spatial (a quaternion, turned about the global axes).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <mpi.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "cli/plugins.hpp"
#include "engine/model.hpp"
#include "engine/rotation.hpp"
#include "io/restart.hpp"
#include "io/standard_outputs.hpp"
#include "scenario/scenario.hpp"
#include "support/harness.hpp"

namespace pdq {
namespace {

// A model's test problem: a scenario (its [model] and [particles] tables) whose particles
// the suite then displaces (and turns) by small deterministic random amounts.
struct Declared {
  std::string scenario;
  double displace = 0;  // amplitude of the random displacements
  double turn = 0;      // of the random rotations (radians, about each axis)
  long steps = 40;      // of the dynamic runs (b), (c)
  // The integ columns holding the force on each particle, by name (moments: the motion's).
  std::vector<std::string> force{"fx", "fy", "fz"};
  // When the force columns hold accelerations: the particle's mass.
  std::function<double(const Particles&, std::size_t)> mass;
};

Declared problem(std::string scenario, double displace, double turn = 0) {
  Declared d;
  d.scenario = std::move(scenario);
  d.displace = displace;
  d.turn = turn;
  return d;
}

// A [particles] table of an nx × ny × nz block generator.
std::string block(const std::string& generator, int nx, int ny, int nz) {
  return fmt::format("[particles]\ngenerator = \"{}\"\nnx = {}\nny = {}\nnz = {}\n", generator, nx,
                     ny, nz);
}

const std::map<std::string, std::vector<Declared>>& declared() {
  static const std::map<std::string, std::vector<Declared>> problems = [] {
    std::map<std::string, Declared> d;
    d["spring"] =
        problem("[model]\nname = \"spring\"\nhorizon = 1.5\ndt = 0.05\ncritical_stretch = 0.2\n" +
                    block("cubic", 5, 4, 4),
                0.05);
    d["lj"] = problem(R"([model]
name = "lj"
dt = 0.002
[particles]
generator = "fcc"
cells = [3, 3, 3]
density = 0.8442
)",
                      0.04);
    const std::string peri =
        "E = 1.0e9\nhorizon = 2.1\ndensity = 1000\ndt = 1.0e-5\ncritical_stretch = 0.5\n" +
        block("cubic", 5, 5, 4) + "[[particles.set]]\nattribute = \"volume\"\nvalue = 1.0\n";
    auto periMass = [](const Particles& P, std::size_t i) {
      return 1000 * P.fixed(i)[P.schema().fixedIndex("volume")];
    };
    d["pmb"] = problem("[model]\nname = \"pmb\"\nsurface_correction = true\n" + peri, 0.01);
    d["pmb"].force = {"ax", "ay", "az"};
    d["pmb"].mass = periMass;
    d["lps"] = problem("[model]\nname = \"lps\"\nnu = 0.25\n" + peri, 0.01);
    d["lps"].force = {"ax", "ay", "az"};
    d["lps"].mass = periMass;
    // A reinforced beam: concrete, a bar, links, supports; co-rotational and damaging.
    d["mplm2d"] = problem(R"([model]
name = "mplm2d"
dt = 1.0e-6
[loading]
load_scale = 500
[particles]
generator = "mplm_beam"
span = 0.3
depth = 0.1
bar_diameter = 0.012
bar_centroid = 0.02
)",
                          2e-5, 2e-4);
    d["morse"] = problem("[model]\nname = \"morse\"\ncutoff = 1.8\n" +
                             block("morse_block", 4, 4, 3) + "spacing = 0.97\n",
                         0.03);
    // fcc at nearest-neighbour distance s = 0.02: density 4 / (s √2)³; co-rotational.
    const std::string fcc = R"(spacing = 0.02
dt = 1.0e-6
[particles]
generator = "fcc"
cells = [3, 3, 2]
density = 176776.69529663686
)";
    d["mplm3d"] = problem("[model]\nname = \"mplm3d\"\n" + fcc, 2e-5, 2e-4);
    std::map<std::string, std::vector<Declared>> all;
    for (auto& [name, one] : d) all[name].push_back(one);
    // Elastic, with turns large enough (relative rotations of tenths of a radian, which
    // would break every concrete interaction) that a moment only right to first order in the
    // rotations fails.
    all["mplm3d"].push_back(
        problem("[model]\nname = \"mplm3d\"\ndamage = false\n" + fcc, 2e-4, 0.2));
    // Reinforced: two bars and closed hoops linked to the concrete, co-rotational, damaging.
    all["mplm3d"].push_back(problem(R"([model]
name = "mplm3d"
spacing = 0.02
dt = 1.0e-6
[particles]
generator = "mplm3d_beam"
length = 0.14
depth = 0.12
width = 0.1
supports = "none"
loading = "none"
bar_diameter = 0.012
bar_cover = 0.015
stirrup_diameter = 0.008
stirrup_spacing = 0.06
stirrup_cover = 0.01
)",
                                    2e-5, 2e-4));
    return all;
  }();
  return problems;
}

int worldRank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// A uniform number in [-1, 1) from a particle's ID and a column.
double noise(Gid id, int column) {
  std::uint64_t z = static_cast<std::uint64_t>(id) * 131 + column + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-52 - 1;
}

// The declared problem as a Problem, perturbed; outputs into `dir`.
Problem problemFor(const std::string& name, const Declared& d, const std::string& dir) {
  const std::string path = "conformance_" + name + "_r" + std::to_string(worldRank()) + ".toml";
  {
    std::ofstream f(path);
    f << "steps = " << d.steps << "\n" << d.scenario;
  }
  Problem pb = readScenario(path).problem;
  ParticleSet& ps = pb.particles;
  const Schema schema = pb.model->schema();
  for (int a = 0; a < 3; ++a) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = 0; k < ps.size(); ++k) {
      lo = std::min(lo, ps.fixedRow(k)[a]);
      hi = std::max(hi, ps.fixedRow(k)[a]);
    }
    if (hi > lo)  // a flat axis stays flat
      for (std::size_t k = 0; k < ps.size(); ++k)
        ps.alterRow(k)[a] += d.displace * noise(ps.gid[k], a);
  }
  const Motion motion = pb.model->motion();
  if (d.turn > 0 && motion.rotation == Rotation::Planar) {
    const int th = schema.alterIndex(motion.orientation[0]);
    for (std::size_t k = 0; k < ps.size(); ++k) ps.alterRow(k)[th] += d.turn * noise(ps.gid[k], 7);
  } else if (d.turn > 0 && motion.rotation == Rotation::Spatial) {
    int q[4];
    for (int c = 0; c < 4; ++c) q[c] = schema.alterIndex(motion.orientation[c]);
    for (std::size_t k = 0; k < ps.size(); ++k) {
      double* a = ps.alterRow(k);
      const Vec th{d.turn * noise(ps.gid[k], 7), d.turn * noise(ps.gid[k], 8),
                   d.turn * noise(ps.gid[k], 9)};
      const Quat t = expRot(th);
      const bool unset = a[q[0]] == 0 && a[q[1]] == 0 && a[q[2]] == 0 && a[q[3]] == 0;
      const Quat r = mul(t, unset ? Quat{1, 0, 0, 0} : Quat{a[q[0]], a[q[1]], a[q[2]], a[q[3]]});
      a[q[0]] = r.w;
      a[q[1]] = r.x;
      a[q[2]] = r.y;
      a[q[3]] = r.z;
    }
  }
  pb.run.outDir = dir;
  pb.output = OutputSettings{};
  pb.output.finalRestart = false;
  return pb;
}

double globalNamed(Simulation& sim, const std::string& name) {
  const auto names = sim.model().globals();
  const auto values = sim.model().globalValues(sim.context());
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw std::runtime_error("no global '" + name + "'");
  return values[it - names.begin()];
}

// (a) Force = −∂U/∂x and moment = −∂U/∂θ for every degree of freedom of every particle
// (spatial rotations: θ a turn about a global axis, q → exp(θ e_k) q), forces and moments
// each against the largest of their kind.
void checkGradient(const std::string& name, const Declared& d) {
  Comm comm;
  Problem pb = problemFor(name, d, "conformance_" + name + "_gradient");
  const std::vector<Gid> ids = pb.particles.gid;
  const auto simulation = makeSimulation(std::move(pb), comm);
  Simulation& sim = *simulation;
  sim.setup();
  Model& model = sim.model();
  Context& ctx = sim.context();
  Particles& P = sim.particles();
  Bonds& B = sim.bonds();
  const Schema& schema = P.schema();
  struct Dof {
    int alter, integ;
    double h;
    int axis;  // a spatial turn about this global axis, or -1: shift the column `alter`
  };
  std::vector<Dof> dofs;
  for (int a = 0; a < sim.decomposition().dim(); ++a) {
    const int c = schema.integIndex(d.force[a]);
    ASSERT_GE(c, 0) << "no integ column '" << d.force[a] << "'";
    dofs.push_back({a, c, 1e-4 * d.displace, -1});
  }
  const std::size_t nForces = dofs.size();
  const Motion motion = model.motion();
  int quat[4] = {-1, -1, -1, -1};
  if (d.turn > 0 && motion.rotation == Rotation::Planar)
    dofs.push_back({schema.alterIndex(motion.orientation[0]), schema.integIndex(motion.moment[0]),
                    1e-4 * d.turn, -1});
  if (d.turn > 0 && motion.rotation == Rotation::Spatial) {
    for (int c = 0; c < 4; ++c) quat[c] = schema.alterIndex(motion.orientation[c]);
    for (int k = 0; k < 3; ++k)
      dofs.push_back({-1, schema.integIndex(motion.moment[k]), 1e-4 * d.turn, k});
  }
  for (const Dof& q : dofs) ASSERT_GE(q.integ, 0);
  auto names = model.globals();
  ASSERT_NE(std::find(names.begin(), names.end(), "potential"), names.end())
      << name << " declares no global \"potential\" (its potential energy)";

  model.force(ctx);
  std::map<Gid, std::vector<double>> force;  // owned particles' generalised forces
  for (std::size_t i = 0; i < P.owned(); ++i)
    for (const Dof& q : dofs)
      force[P.gid(i)].push_back(P.integ(i)[q.integ] * (d.mass ? d.mass(P, i) : 1.0));
  double scales[2] = {0, 0};  // forces, moments
  for (auto& [g, f] : force)
    for (std::size_t k = 0; k < f.size(); ++k)
      scales[k >= nForces] = std::max(scales[k >= nForces], std::fabs(f[k]));
  for (double& s : scales) s = ctx.max(s);
  ASSERT_GT(scales[0], 0) << "the perturbed lattice of " << name << " carries no force";
  if (dofs.size() > nForces) {
    ASSERT_GT(scales[1], 0) << "the perturbed lattice of " << name << " carries no moment";
  }
  std::vector<double> bondState(B.count() * B.nAttr());
  for (std::size_t b = 0; b < B.count(); ++b)
    std::copy_n(B.attr(b), B.nAttr(), &bondState[b * B.nAttr()]);
  auto alive = [&] {
    long k = 0;
    for (std::size_t b = 0; b < B.count(); ++b) k += B.alive(b);
    return ctx.count(k);
  };
  const long aliveBefore = alive();
  // The energy with one coordinate of particle g shifted by `by`, at the bond state of the
  // unshifted lattice (damage is a history, not a function of the positions).
  auto energyShifted = [&](Gid g, const Dof& q, double by) {
    std::size_t mine = P.owned();
    for (std::size_t i = 0; i < P.owned(); ++i)
      if (P.gid(i) == g) mine = i;
    double saved[4] = {0, 0, 0, 0};
    if (mine < P.owned() && q.axis < 0) {
      saved[0] = P.alter(mine)[q.alter];
      P.alter(mine)[q.alter] = saved[0] + by;
    } else if (mine < P.owned()) {
      double* a = P.alter(mine);
      for (int c = 0; c < 4; ++c) saved[c] = a[quat[c]];
      Vec turn{0, 0, 0};
      turn[q.axis] = by;
      const Quat r = mul(expRot(turn), {saved[0], saved[1], saved[2], saved[3]});
      a[quat[0]] = r.w;
      a[quat[1]] = r.x;
      a[quat[2]] = r.y;
      a[quat[3]] = r.z;
    }
    sim.procCube().halo();
    model.force(ctx);
    for (std::size_t b = 0; b < B.count(); ++b)
      std::copy_n(&bondState[b * B.nAttr()], B.nAttr(), B.attr(b));
    const double u = globalNamed(sim, "potential");
    if (mine < P.owned() && q.axis < 0) P.alter(mine)[q.alter] = saved[0];
    if (mine < P.owned() && q.axis >= 0)
      for (int c = 0; c < 4; ++c) P.alter(mine)[quat[c]] = saved[c];
    sim.procCube().halo();
    return u;
  };
  double worst = 0;
  long checked = 0;
  for (Gid g : ids)
    for (std::size_t k = 0; k < dofs.size(); ++k) {
      const double scale = scales[k >= nForces];
      const auto it = force.find(g);
      const double f = ctx.max(it != force.end() ? it->second[k] : -INFINITY);
      const double up = energyShifted(g, dofs[k], dofs[k].h);
      const double down = energyShifted(g, dofs[k], -dofs[k].h);
      const double fd = -(up - down) / (2 * dofs[k].h);
      worst = std::max(worst, std::fabs(f - fd) / scale);
      EXPECT_NEAR(f, fd, 1e-6 * scale)
          << name << ": particle " << g << ", " << (k < nForces ? "force " : "moment ")
          << (k < nForces ? k : k - nForces);
      ++checked;
    }
  EXPECT_EQ(alive(), aliveBefore) << "bonds broke during the finite differences";
  EXPECT_EQ(checked, static_cast<long>(ids.size() * dofs.size()));
  if (worldRank() == 0)
    std::cout << name << ": " << checked
              << " derivatives, largest |F + dU/dx| / max|F| (of its kind) = " << worst << "\n";
}

test::State runOn(const std::string& name, const Declared& d, int ranks, int threads,
                  const std::string& dir) {
  omp_set_num_threads(threads);
  MPI_Comm c = test::firstRanks(ranks);
  test::State s;
  if (c != MPI_COMM_NULL) {
    Comm comm(c);
    const auto sim = makeSimulation(problemFor(name, d, dir), comm);
    sim->run();
    s = test::gatherState(*sim);
  }
  if (c != MPI_COMM_NULL) MPI_Comm_free(&c);
  return test::toWorldRoot(s, 0);
}

// (b) 1 rank 1 thread against 3 ranks and 2 threads.
void checkRanksAndThreads(const std::string& name, const Declared& d) {
  const std::string dir = "conformance_" + name + "_ranks";
  const test::State reference = runOn(name, d, 1, 1, dir);
  const int pairs[3][2] = {{3, 1}, {1, 2}, {3, 2}};
  for (const auto& rt : pairs) {
    const test::State other = runOn(name, d, rt[0], rt[1], dir);
    if (worldRank() == 0) {
      ASSERT_FALSE(reference.particles.empty());
      EXPECT_TRUE(other == reference) << name << " on " << rt[0] << " ranks, " << rt[1]
                                      << " threads differs from 1 rank, 1 thread";
    }
  }
  omp_set_num_threads(2);
}

// (c) A restart at a random step ends as the uninterrupted run.
void checkRestart(const std::string& name, const Declared& d) {
  long at = 0;
  if (worldRank() == 0) {
    std::random_device seed;
    at = std::uniform_int_distribution<long>(1, d.steps - 1)(seed);
  }
  MPI_Bcast(&at, 1, MPI_LONG, 0, MPI_COMM_WORLD);
  SCOPED_TRACE("restart at step " + std::to_string(at));
  const std::string dir = "conformance_" + name + "_restart";
  if (worldRank() == 0) std::filesystem::remove_all(dir);
  MPI_Barrier(MPI_COMM_WORLD);
  Comm comm;
  test::State full, resumed;
  {
    Problem pb = problemFor(name, d, dir);
    pb.output.restartEvery = at;
    const auto sim = makeSimulation(std::move(pb), comm);
    sim->run();
    full = test::gatherState(*sim);
  }
  {
    Problem pb = problemFor(name, d, dir + "_again");
    pb.restart = readRestart(restartPath(dir, at), pb);
    EXPECT_EQ(pb.run.firstStep, at);
    const auto sim = makeSimulation(std::move(pb), comm);
    sim->run();
    resumed = test::gatherState(*sim);
  }
  if (worldRank() == 0) {
    ASSERT_FALSE(full.particles.empty());
    EXPECT_TRUE(full == resumed) << name << ": the run restarted at step " << at
                                 << " differs from the uninterrupted one";
  }
}

void expectDistinct(const std::string& what, const std::vector<std::string>& names) {
  std::set<std::string> seen;
  for (const auto& s : names) {
    EXPECT_FALSE(s.empty()) << what << " has an empty name";
    EXPECT_TRUE(seen.insert(s).second) << what << " declares '" << s << "' twice";
  }
}

// (d) Names: distinct within each group; every attribute found by its name at its column;
// every field and global evaluated by name.
void checkNames(const std::string& name, const Declared& d) {
  Comm comm;
  const auto simulation =
      makeSimulation(problemFor(name, d, "conformance_" + name + "_names"), comm);
  Simulation& sim = *simulation;
  sim.setup();
  Model& model = sim.model();
  const Schema s = model.schema();
  expectDistinct(name + " fixed attributes", s.fixed);
  expectDistinct(name + " alterable attributes", s.alter);
  expectDistinct(name + " integ columns", s.integ);
  expectDistinct(name + " bond attributes", s.bond);
  for (int k = 0; k < s.nFixed(); ++k) EXPECT_EQ(s.fixedIndex(s.fixed[k]), k);
  for (int k = 0; k < s.nAlter(); ++k) EXPECT_EQ(s.alterIndex(s.alter[k]), k);
  for (int k = 0; k < s.nInteg(); ++k) EXPECT_EQ(s.integIndex(s.integ[k]), k);
  for (int k = 0; k < s.nBond(); ++k) EXPECT_EQ(s.bondIndex(s.bond[k]), k);
  EXPECT_EQ(s.fixedIndex("X"), 0);
  EXPECT_EQ(s.alterIndex("x"), 0);
  const auto fields = model.fields();
  expectDistinct(name + " fields", fields);
  std::vector<double> out(sim.particles().owned());
  for (const auto& f : fields) {
    const int k = static_cast<int>(std::find(fields.begin(), fields.end(), f) - fields.begin());
    std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
    model.field(sim.context(), k, out);
    for (double v : out) EXPECT_TRUE(std::isfinite(v)) << name << " field '" << f << "'";
  }
  const auto globals = model.globals();
  expectDistinct(name + " globals", globals);
  EXPECT_EQ(model.globalValues(sim.context()).size(), globals.size())
      << name << " gives as many global values as it names";
  for (const auto& g : globals) EXPECT_TRUE(std::isfinite(globalNamed(sim, g))) << name << " " << g;
}

TEST(Conformance, EveryRegisteredModel) {
  cli::loadPlugins({PDQ_PLUGIN_MORSE});
  int world = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &world);
  ASSERT_GE(world, 3) << "the suite compares 1 and 3 ranks";
  const auto models = ModelRegistry::list();
  ASSERT_NE(std::find_if(models.begin(), models.end(), [](auto& m) { return m.first == "morse"; }),
            models.end())
      << "the example plugin did not register";
  for (const auto& [name, description] : models) {
    SCOPED_TRACE("model " + name);
    const auto it = declared().find(name);
    if (it == declared().end()) {
      ADD_FAILURE() << "model '" << name
                    << "' has no conformance problem: describe one in "
                       "tests/conformance/conformance_test.cpp";
      continue;
    }
    for (std::size_t k = 0; k < it->second.size(); ++k) {
      SCOPED_TRACE("problem " + std::to_string(k + 1));
      // Files of a second problem go apart.
      const std::string tag = k == 0 ? name : name + "_" + std::to_string(k + 1);
      checkNames(tag, it->second[k]);
      checkGradient(tag, it->second[k]);
      checkRanksAndThreads(tag, it->second[k]);
      checkRestart(tag, it->second[k]);
    }
  }
}

}  // namespace
}  // namespace pdq
