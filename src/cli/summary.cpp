#include "cli/summary.hpp"

#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>

#include "engine/decomposition.hpp"
#include "engine/error.hpp"
#include "engine/memory.hpp"

namespace pdq::cli {

namespace {

std::string megabytes(double bytes) { return fmt::format("{:.1f} MB", bytes / 1e6); }

std::string axes(const std::array<int, 3>& v, int dim) {
  std::string s = std::to_string(v[0]);
  for (int a = 1; a < dim; ++a) s += " x " + std::to_string(v[a]);
  return s;
}

}  // namespace

std::string summary(Simulation& sim, const std::string& modelName, const std::string& source,
                    int ranks) {
  Comm& comm = sim.comm();
  const Particles& P = sim.particles();
  const Bonds& B = sim.bonds();
  const Schema& s = P.schema();
  const Decomposition& dec = sim.decomposition();
  const Domain& dom = dec.domain();
  const int dim = dec.dim();

  const double owned = static_cast<double>(comm.sum(static_cast<long>(P.owned())));
  const double bondEntries = static_cast<double>(comm.sum(static_cast<long>(B.count())));
  const double maxOwned = comm.max(static_cast<double>(P.owned()));
  const double maxGhosts = comm.max(static_cast<double>(P.ghosts()));
  // The particle and bond tables of this rank (the engine's own data; a model's
  // neighbour lists and scratch come on top, and the peak below includes them).
  const double tables = tableBytes(s, static_cast<double>(P.local()),
                                   static_cast<double>(P.owned()), static_cast<double>(B.count()));
  ExactSum acc;
  acc.add(tables);
  const double tablesTotal = comm.sum(acc), tablesMax = comm.max(tables);
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  const double peak = comm.max(static_cast<double>(ru.ru_maxrss) * 1024);  // kB on Linux
  std::array<int, 3> core{};  // the most cells a rank's core has along each axis
  for (int a = 0; a < 3; ++a) core[a] = static_cast<int>(comm.max(double(dec.coreCells(a))));
  if (!comm.root()) return "";

  const double dt = sim.context().dt();
  const long first = sim.config().firstStep, steps = sim.config().steps;
  std::string o;
  o += fmt::format("input         {}\n", source);
  o += fmt::format("model         {}\n", modelName);
  o += fmt::format("particles     {:.0f}\n", owned);
  if (s.nBond() > 0 || bondEntries > 0)
    o += fmt::format("bonds         {:.0f} (each stored with both its particles)\n",
                     bondEntries / 2);
  o += fmt::format("attributes    fixed: {}; alterable: {}", fmt::join(s.fixed, " "),
                   fmt::join(s.alter, " "));
  if (s.nBond()) o += fmt::format("; bond: {}", fmt::join(s.bond, " "));
  o += "\n";
  o += fmt::format("time step     {:.6g}\n", dt);
  o += fmt::format("steps         {} to {} (simulated time {:.6g} to {:.6g})\n", first, steps,
                   first * dt, steps * dt);
  o += fmt::format("dimension     {}D\n", dim);
  std::string box;
  for (int a = 0; a < dim; ++a)
    box += fmt::format("{}{}: [{:.6g}, {:.6g}]{}", a ? "  " : "", "XYZ"[a], dom.lo[a], dom.hi[a],
                       dom.periodic[a] ? " periodic" : "");
  o += fmt::format("domain        {}\n", box);
  std::array<int, 3> cells{}, procs{};
  for (int a = 0; a < 3; ++a) {
    cells[a] = dec.globalCells(a);
    procs[a] = dec.procs(a);
  }
  std::string size;
  for (int a = 0; a < dim; ++a) size += fmt::format("{}{:.6g}", a ? " x " : "", dec.cellSize(a));
  o += fmt::format("cells         {} (cell size {})\n", axes(cells, dim), size);
  o += fmt::format(
      "processors    {} = {} rank(s); up to {} cells, {:.0f} particles and {:.0f} "
      "ghosts per rank\n",
      axes(procs, dim), comm.size(), axes(core, dim), maxOwned, maxGhosts);
  o += fmt::format(
      "memory        particle and bond tables {} in all, {} on the largest rank; "
      "peak {} per rank during setup\n",
      megabytes(tablesTotal), megabytes(tablesMax), megabytes(peak));
  if (ranks > 0) {
    const double minCell =
        sim.config().minCellSize > 0 ? sim.config().minCellSize : sim.model().horizon();
    const std::array<int, 3> asked = sim.config().procs;
    Decomposition d(dom, minCell, asked, ranks, 0, source, sim.model().cellDivisions());
    std::array<int, 3> p{}, c{};
    for (int a = 0; a < 3; ++a) {
      p[a] = d.procs(a);
      c[a] = (d.globalCells(a) + p[a] - 1) / p[a];
    }
    o += fmt::format(
        "on {} ranks    processors {}, about {} cells per rank, about {:.0f} "
        "particles per rank\n",
        ranks, axes(p, dim), axes(c, dim), owned / ranks);
  }
  return o;
}

std::string estimateSummary(const SizeEstimate& e, const Model& model, bool& fits) {
  const Schema s = model.schema();
  const double particles = e.particles + e.extraParticles;
  const bool lattice = !e.primitive.empty();
  const bool bonded = model.bondsWithinHorizon();
  const double bonds = bonded ? e.pairsWithin(model.horizon()) + e.extraPairs : 0;
  std::string o = "estimate      from the scenario, before anything is made:\n";
  o += fmt::format("  particles   {:.0f}\n", particles);
  if (!bonded)
    o += "  bonds       none (the model keeps no bonds)\n";
  else if (lattice)
    o += fmt::format("  bonds       {:.0f} (the lattice's pairs within the horizon {:.6g})\n",
                     bonds, model.horizon());
  else
    o += "  bonds       not estimated (particles from files: no lattice)\n";
  if (lattice) {
    // Cells as the decomposition lays them: the box and a margin of one horizon each side.
    std::string cells;
    double count = 1;
    for (int a = 0; a < 3; ++a) {
      if (!(e.hi[a] > e.lo[a])) continue;
      const double n = std::max(
          1.0, std::floor((e.hi[a] - e.lo[a] + 2 * model.horizon()) / model.minCellSize()));
      count *= n;
      cells += fmt::format("{}{:.0f}", cells.empty() ? "" : " x ", n);
    }
    o += fmt::format("  cells       {} ({:.0f}; cell size {:.6g})\n", cells, count,
                     model.minCellSize());
  }
  o += fmt::format("  attributes  {} fixed, {} alterable, {} integration a particle; {} a bond\n",
                   s.nFixed(), s.nAlter(), s.nInteg(), s.nBond());
  const double bytes = tableBytes(s, particles, particles, 2 * bonds);
  const double have = availableMemory();
  fits = bytes <= have;
  o += fmt::format(
      "  memory      {} for the particle and bond tables (a model's own arrays come on top); "
      "{} available{}\n",
      byteText(bytes), byteText(have), fits ? "" : ": it does not fit");
  return o;
}

}  // namespace pdq::cli
