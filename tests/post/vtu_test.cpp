// The ParaView output, read back by ParaView's own reader (pvpython): the series has
// every output step, the particle count and a field match the run exactly, and every
// bond appears once with its attribute — at any number of ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "engine/error.hpp"
#include "io/standard_outputs.hpp"
#include "io/vtu_output.hpp"
#include "post/snapshot.hpp"
#include "spring_lattice.hpp"
#include "support/mplm3d_bar.hpp"

namespace pdq {
namespace {

// Runs pvpython on rank 0 with a clean environment (it must not join our MPI job).
std::string pvpython(const std::string& args, const std::string& outFile) {
  const std::string script = std::string(std::getenv("PDQ_SOURCE_DIR")) + "/tests/post/read_vtu.py";
  const std::string cmd = "env -i PATH=/usr/bin:/bin HOME=/tmp pvpython " + script + " " + args +
                          " > " + outFile + " 2> " + outFile + ".err";
  const int rc = std::system(cmd.c_str());
  std::ifstream in(outFile);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(rc, 0) << cmd << "\n" << ss.str();
  return ss.str();
}

TEST(Vtu, ParaViewReadsParticlesAndBonds) {
  Comm comm;
  const std::string dir = "vtu_np" + std::to_string(comm.size());
  if (comm.root()) std::filesystem::remove_all(dir);
  comm.barrier();
  const int nx = 12, ny = 7;
  auto sim = test::springLattice(comm, nx, ny, 20, dir);
  sim->addOutput(std::make_unique<VtuOutput>(VtuOptions{.every = 8}));
  sim->run();
  const auto vx = test::gatherAlter(*sim, 3);
  const auto bonds = test::gatherBonds(*sim);
  if (!comm.root()) return;

  // Particles: steps 0, 8, 16 and the last (20), at times step * dt.
  std::istringstream out(pvpython(dir + "/particles.pvd vx " + dir + "/particles_bonds.pvd broken",
                                  dir + "/read.txt"));
  std::string word, line;
  std::getline(out, line);  // series
  out >> word;
  ASSERT_EQ(word, "times");
  for (double t : {0.0, 0.4, 0.8, 1.0}) {
    double v;
    out >> v;
    EXPECT_DOUBLE_EQ(v, t);
  }
  long points = -1, cells = -1;
  out >> word >> points >> word >> cells;
  EXPECT_EQ(points, nx * ny);
  EXPECT_EQ(cells, nx * ny);
  std::map<long, double> seen;
  long id;
  double v;
  while (out >> word && word == "value" && out >> id >> v) seen[id] = v;
  ASSERT_EQ(seen.size(), vx.size());
  for (const auto& [gid, value] : vx) EXPECT_EQ(seen.at(gid), value) << "particle " << gid;

  // Bonds: each once, with its 'broken' flag; some broke and some did not.
  ASSERT_EQ(word, "series");
  std::getline(out, line);
  std::getline(out, line);  // times
  out >> word >> points >> word >> cells;
  EXPECT_EQ(cells, static_cast<long>(bonds.size()));
  std::map<std::pair<long, long>, double> seenBonds;
  long a, b;
  while (out >> word >> a >> b >> v) seenBonds[{a, b}] = v;
  EXPECT_EQ(seenBonds, bonds);
  int broken = 0;
  for (const auto& [k, flag] : bonds) broken += flag != 0;
  EXPECT_GT(broken, 0);
  EXPECT_LT(broken, static_cast<int>(bonds.size()));
}

// A cracking 3D lattice (mplm3d): every particle's orientation, rotation vector (also as
// one 3-component array) and damage, and every interaction once as a line with its damage,
// read back by ParaView as the run left them.
TEST(Vtu, ParaViewReadsMplm3dRotationsAndDamage) {
  Comm comm;
  const std::string dir = "vtu_mplm3d_np" + std::to_string(comm.size());
  if (comm.root()) std::filesystem::remove_all(dir);
  comm.barrier();
  Problem pb = test::crackingBar3d();
  pb.run.loading.rampTime = 4e-5;  // s: about 200 steps
  pb.run.steps = 300;
  pb.run.outDir = dir;
  const auto sim = makeSimulation(std::move(pb), comm);
  sim->addOutput(std::make_unique<VtuOutput>(VtuOptions{.every = 0}));
  sim->run();
  const post::Snapshot snap = post::gatherSnapshot(sim->context(), sim->model(), comm, sim->step());
  if (!comm.root()) return;

  std::istringstream out(pvpython(dir + "/particles.pvd rotation,rx,ry,rz,qw,qx,qy,qz,damage " +
                                      dir + "/particles_bonds.pvd omega_t,omega_c",
                                  dir + "/read.txt"));
  std::string word, line;
  std::getline(out, line);  // series
  std::getline(out, line);  // times
  long points = -1, cells = -1;
  out >> word >> points >> word >> cells;
  ASSERT_EQ(points, static_cast<long>(snap.particles()));
  auto quantity = [&](const std::string& name) {
    const auto k = std::find(snap.names.begin(), snap.names.end(), name) - snap.names.begin();
    EXPECT_LT(k, static_cast<long>(snap.names.size())) << name;
    return snap.values.at(k);
  };
  const std::vector<std::string> names{"rx", "ry", "rz", "rx", "ry",    "rz",
                                       "qw", "qx", "qy", "qz", "damage"};
  std::vector<std::vector<double>> expected;
  for (const auto& n : names) expected.push_back(quantity(n));
  double turned = 0, damaged = 0;
  long read = 0;
  while (out >> word && word == "value") {
    long id;
    out >> id;
    const std::size_t i = static_cast<std::size_t>(
        std::lower_bound(snap.id.begin(), snap.id.end(), id) - snap.id.begin());
    ASSERT_LT(i, snap.particles());
    for (std::size_t k = 0; k < names.size(); ++k) {
      double v;
      out >> v;
      EXPECT_EQ(v, expected[k][i]) << names[k] << " of particle " << id;
    }
    turned = std::max(turned, std::abs(expected[0][i]) + std::abs(expected[2][i]));
    damaged = std::max(damaged, expected[10][i]);
    ++read;
  }
  EXPECT_EQ(read, points);
  EXPECT_GT(turned, 0) << "the particles should turn";
  EXPECT_GT(damaged, 0) << "the run should damage the lattice";

  // Interactions: each once as a line, with its tensile and compressive damage.
  ASSERT_EQ(word, "series");
  std::getline(out, line);
  std::getline(out, line);  // times
  out >> word >> points >> word >> cells;
  ASSERT_EQ(cells, static_cast<long>(snap.bonds.size()));
  const std::size_t nb = snap.bondNames.size();
  const auto kt =
      std::find(snap.bondNames.begin(), snap.bondNames.end(), "omega_t") - snap.bondNames.begin();
  std::map<std::pair<long, long>, std::array<double, 2>> bonds, seen;
  for (std::size_t b = 0; b < snap.bonds.size(); ++b)
    bonds[{snap.id[snap.bonds[b][0]], snap.id[snap.bonds[b][1]]}] = {
        snap.bondAttrs[b * nb + kt], snap.bondAttrs[b * nb + kt + 1]};
  long a, b;
  double t, c;
  while (out >> word >> a >> b >> t >> c) seen[{a, b}] = {t, c};
  EXPECT_EQ(seen, bonds);
  int cracked = 0;
  for (const auto& [key, omega] : bonds) cracked += omega[0] >= 1;
  EXPECT_GT(cracked, 0);
}

// A restarted run (first step 8) continues the earlier run's series: the entries before
// its first step are kept, the rest replaced, none doubled.
TEST(Vtu, RestartContinuesTheSeries) {
  Comm comm;
  const std::string dir = "vtu_restart_np" + std::to_string(comm.size());
  if (comm.root()) std::filesystem::remove_all(dir);
  comm.barrier();
  auto first = test::springLattice(comm, 6, 4, 12, dir);
  first->addOutput(std::make_unique<VtuOutput>(VtuOptions{.every = 8, .bonds = false}));
  first->run();  // steps 0, 8, 12
  auto again = test::springLattice(comm, 6, 4, 20, dir, 8);
  again->addOutput(std::make_unique<VtuOutput>(VtuOptions{.every = 8, .bonds = false}));
  again->run();  // steps 8, 16, 20
  if (!comm.root()) return;
  std::ifstream in(dir + "/particles.pvd");
  std::string line, files;
  while (std::getline(in, line)) {
    const auto at = line.find("file=\"");
    if (at != std::string::npos)
      files += line.substr(at + 6, line.find('"', at + 6) - at - 6) + " ";
  }
  EXPECT_EQ(files,
            "particles/particles_000000.pvtu particles/particles_000008.pvtu "
            "particles/particles_000016.pvtu particles/particles_000020.pvtu ");
}

TEST(Vtu, OptionsFromAScenarioTable) {
  Params t("[output.paraview]");
  t.set("every", "100", "beam.toml", 20);
  t.set("bonds", "false", "beam.toml", 21);
  const VtuOptions o = vtuOptions(t);
  EXPECT_EQ(o.every, 100);
  EXPECT_FALSE(o.bonds);
  EXPECT_TRUE(o.atEnd);
  t.set("every", "-1", "beam.toml", 20);
  try {
    vtuOptions(t);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 20);
  }
}

}  // namespace
}  // namespace pdq
