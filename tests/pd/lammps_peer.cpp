#include "lammps_peer.hpp"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "engine/atomic_file.hpp"
#include "engine/error.hpp"
#include "models/peri/peri_model.hpp"
#include "prep/lattice.hpp"

namespace pdq::lammps {

namespace {
std::string num(double v) {
  std::ostringstream os;
  os << std::setprecision(17) << v;
  return os.str();
}
}  // namespace

void Block::velocity(const double* X, double* v) const {
  const double L = n * s, k = 2 * std::numbers::pi / L;
  v[0] = v0 * std::sin(k * X[0]) * std::cos(0.5 * k * X[1]);
  v[1] = v0 * std::sin(k * X[1] + 1.0) * std::cos(0.5 * k * X[2]);
  v[2] = v0 * std::sin(k * X[2] + 2.0) * std::cos(0.5 * k * X[0]);
}

Params blockParams(const Block& bl, const std::string& model) {
  Params p("block");
  p.set("E", num(bl.E));
  if (model == "lps") p.set("nu", num(bl.nu));
  p.set("horizon", num(bl.delta()));
  p.set("density", num(bl.rho));
  p.set("dt", num(bl.dt));
  p.set("lattice_spacing", num(bl.s));
  return p;
}

ParticleSet blockParticles(const Block& bl, const Schema& schema) {
  ParticleSet ps;
  ps.nFixed = schema.nFixed();
  ps.nAlter = schema.nAlter();
  prep::appendLattice(ps, prep::cubicLattice(bl.n, bl.n, bl.n, bl.s));
  const int vol = schema.fixedIndex("volume"), vx = schema.alterIndex("vx");
  const int fz = schema.fixedIndex("fz");
  for (std::size_t k = 0; k < ps.size(); ++k) {
    ps.fixedRow(k)[vol] = bl.s * bl.s * bl.s;
    if (ps.fixedRow(k)[2] > (bl.n - 1.5) * bl.s) ps.fixedRow(k)[fz] = bl.topLoad;
    bl.velocity(ps.fixedRow(k), ps.alterRow(k) + vx);
  }
  return ps;
}

void writeLammps(const Block& bl, const std::string& model, long steps, const std::string& dir,
                 const ParticleSet& ps) {
  std::ostringstream d;
  d << std::setprecision(17);
  d << "pdq block for LAMMPS peri (written by pd_bench)\n\n"
    << ps.size() << " atoms\n1 atom types\n\n";
  const double lo = -bl.s, hi = bl.n * bl.s;
  for (const char* ax : {"x", "y", "z"}) d << lo << " " << hi << " " << ax << "lo " << ax << "hi\n";
  d << "\nAtoms # peri\n\n";
  for (std::size_t k = 0; k < ps.size(); ++k) {
    const double* X = ps.fixedRow(k);
    d << ps.gid[k] << " 1 " << bl.s * bl.s * bl.s << " " << bl.rho << " " << X[0] << " " << X[1]
      << " " << X[2] << "\n";
  }
  d << "\nVelocities\n\n";
  for (std::size_t k = 0; k < ps.size(); ++k) {
    double v[3];
    bl.velocity(ps.fixedRow(k), v);
    d << ps.gid[k] << " " << v[0] << " " << v[1] << " " << v[2] << "\n";
  }
  writeFileAtomically(dir + "/lammps.data", d.str());
  std::ostringstream in;
  in << std::setprecision(17);
  in << "# The pd_bench block in LAMMPS (units si: m, kg, s, Pa)\nunits si\nboundary s s s\n"
        "atom_style peri\natom_modify map array\n"
     << "lattice sc " << bl.s << "\nread_data lammps.data\n";
  if (model == "pmb") {
    in << "pair_style peri/pmb\npair_coeff * * " << peri::pmbMicromodulus(3, bl.E, bl.delta(), 1)
       << " " << bl.delta() << " 1.0e10 0.0\n";
  } else {
    const double K = bl.E / (3 * (1 - 2 * bl.nu)), G = bl.E / (2 * (1 + bl.nu));
    in << "pair_style peri/lps\npair_coeff * * " << K << " " << G << " " << bl.delta()
       << " 1.0e10 0.0\n";
  }
  // LAMMPS judges bond breaking against the previous step's critical stretch s0, which
  // is not yet set on the first step (in the Debian 2021 package, peri/lps breaks every
  // stretched bond there); a first step of zero length stretches nothing and sets it.
  in << "neighbor " << 0.1 * bl.s << " bin\nfix 1 all nve\n";
  if (bl.topLoad != 0)  // LAMMPS's peri forces are force densities: the load over the volume
    in << "region top block INF INF INF INF " << (bl.n - 1.5) * bl.s
       << " INF units box\ngroup top region top\nfix 2 top addforce 0 0 "
       << bl.topLoad / (bl.s * bl.s * bl.s) << "\n";
  in << "timestep 0\nrun 1\ntimestep " << bl.dt << "\nthermo " << steps << "\nrun " << steps << "\n"
     << "write_dump all custom lammps.dump id x y z modify sort id format float %.17g\n";
  writeFileAtomically(dir + "/lammps.in", in.str());
}

// Reads "ID ux uy uz" (pdq.disp) or a LAMMPS dump of "id x y z" (then the lattice
// position is subtracted using the block's data file next to it).
Displacements readDisplacements(const std::string& file) {
  Displacements u;
  std::ifstream in(file);
  if (!in) throw InputError(file, 0, "cannot open");
  const bool dump = file.size() > 5 && file.substr(file.size() - 5) == ".dump";
  std::map<long, std::array<double, 3>> ref;
  if (dump) {
    const std::string data = file.substr(0, file.rfind('/') + 1) + "lammps.data";
    std::ifstream d(data);
    std::string line;
    bool atoms = false;
    while (std::getline(d, line)) {
      if (line.rfind("Atoms", 0) == 0) {
        atoms = true;
        continue;
      }
      if (line.rfind("Velocities", 0) == 0) break;
      std::istringstream ls(line);
      long id;
      int type;
      double v, rho, x, y, z;
      if (atoms && (ls >> id >> type >> v >> rho >> x >> y >> z)) ref[id] = {x, y, z};
    }
  }
  std::string line;
  int lineNo = 0;
  bool inAtoms = !dump;
  while (std::getline(in, line)) {
    ++lineNo;
    if (dump && line.rfind("ITEM: ATOMS", 0) == 0) {
      inAtoms = true;
      continue;
    }
    if (!inAtoms || line.rfind("ITEM", 0) == 0) continue;
    std::istringstream ls(line);
    long id;
    double a, b, c;
    if (!(ls >> id >> a >> b >> c))
      throw InputError(file, lineNo, "expected: ID and three numbers");
    if (dump) {
      auto it = ref.find(id);
      if (it == ref.end()) throw InputError(file, lineNo, "atom not in lammps.data");
      a -= it->second[0];
      b -= it->second[1];
      c -= it->second[2];
    }
    u[id] = {a, b, c};
  }
  return u;
}

Difference compare(const Displacements& a, const Displacements& b, const std::string& nameB) {
  if (a.size() != b.size()) throw InputError(nameB, 0, "a different number of particles");
  Difference d;
  d.particles = a.size();
  for (auto& [id, ua] : a) {
    auto it = b.find(id);
    if (it == b.end()) throw InputError(nameB, 0, "particle " + std::to_string(id) + " missing");
    const auto& ub = it->second;
    d.maxU = std::max(d.maxU, std::hypot(ua[0], ua[1], ua[2]));
    d.maxDiff = std::max(d.maxDiff, std::hypot(ua[0] - ub[0], ua[1] - ub[1], ua[2] - ub[2]));
  }
  return d;
}

}  // namespace pdq::lammps
