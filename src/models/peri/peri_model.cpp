#include "models/peri/peri_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "engine/error.hpp"

namespace pdq::peri {

double partialVolume(double r0, double delta, double spacing) {
  if (spacing <= 0 || r0 < delta - 0.5 * spacing) return 1.0;
  return (delta + 0.5 * spacing - r0) / spacing;
}

double pmbMicromodulus(int dim, double E, double delta, double thickness) {
  const double pi = std::numbers::pi;
  if (dim == 3) return 12.0 * E / (pi * delta * delta * delta * delta);
  return 9.0 * E / (pi * thickness * delta * delta * delta);
}

namespace {
double positive(const Params& p, const std::string& key) {
  const double v = p.number(key);
  if (!(v > 0)) {
    const auto r = p.raw(key);
    throw InputError(r ? r->file : p.owner(), r ? r->line : 0, key + " must be positive");
  }
  return v;
}
}  // namespace

void PeriModel::configure(const Params& p) {
  E_ = positive(p, "E");
  delta_ = positive(p, "horizon");
  density_ = positive(p, "density");
  dt_ = positive(p, "dt");
  thickness_ = p.number("thickness", 1.0, 1e-300, 1e300);
  criticalStretch_ = p.number("critical_stretch", 0.0, 0.0, 1e300);
  damping_ = p.number("damping", 0.0, 0.0, 1e300);
  spacing_ = p.number("lattice_spacing", 0.0, 0.0, 1e300);
  if (p.has("notch")) {
    notch_ = p.numbers("notch");
    if (notch_.empty() || notch_.size() % 4 != 0) {
      const auto r = p.raw("notch");
      throw InputError(r->file, r->line, "notch needs X1 Y1 X2 Y2 for each segment");
    }
  }
  configureModel(p);
}

Schema PeriModel::schema() const {
  std::vector<std::string> alter{"vx", "vy", "vz"};
  for (auto& a : alterExtra()) alter.push_back(a);
  std::vector<std::string> bond{"xi", "weight"};
  for (auto& b : bondExtra()) bond.push_back(b);
  Schema s = Schema::make({"bc_x", "bc_y", "bc_z", "fx", "fy", "fz", "volume"}, alter,
                          {"ax", "ay", "az"}, bond);
  s.haloColumns = 3;  // bonds read their ghost partners' positions only
  return s;
}

void PeriModel::setup(Context& ctx) {
  dim_ = ctx.dim();
  if (dim_ < 2) throw InputError("particles", 0, "peridynamic models need a 2D or 3D particle set");
  Particles& P = ctx.particles;
  for (std::size_t i = 0; i < P.owned(); ++i)
    if (!(P.fixed(i)[VOLUME] > 0)) {
      std::ostringstream os;
      os << "particle " << P.gid(i) << " has volume " << P.fixed(i)[VOLUME]
         << "; every particle needs a positive volume";
      throw InputError("particles", 0, os.str());
    }
  // Bonds join every pair within the horizon in the reference configuration; the test
  // d² <= δ² is the one LAMMPS's PERI package uses, so both codes bond the same pairs.
  const double d2max = delta_ * delta_;
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const double* Xi = P.fixed(i);
    ctx.forEachNearby(i, [&](std::size_t j) {
      const double* Xj = P.fixed(j);
      const double dx = Xi[0] - Xj[0], dy = Xi[1] - Xj[1], dz = Xi[2] - Xj[2];
      if (dx * dx + dy * dy + dz * dz <= d2max && !cutByNotch(Xi, Xj)) ctx.bonds.add(i, P.gid(j));
    });
  }
  ctx.setDt(dt_);
}

void PeriModel::prepare(Context& ctx) {
  Particles& P = ctx.particles;
  Bonds& B = ctx.bonds;
  std::vector<double> volume(B.count());
  for (std::size_t i = 0; i < P.owned(); ++i) {
    const double* Xi = P.fixed(i);
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      double* a = B.attr(b);
      // A restart restored XI and WEIGHT; a fresh bond has XI = 0 and is intact.
      const bool intact = B.alive(b) && (a[XI] == 0 || a[WEIGHT] != 0);
      // A restored weight of 0 broke before: dead from here, as the kernels, which judge only
      // bonds of nonzero weight, take it to be (a file may not say it is dead).
      if (!intact && B.alive(b)) B.kill(b);
      const double* Xj = P.fixed(B.partner(b));
      const double dx = Xi[0] - Xj[0], dy = Xi[1] - Xj[1], dz = Xi[2] - Xj[2];
      a[XI] = std::sqrt(dx * dx + dy * dy + dz * dz);
      volume[b] = intact ? Xj[VOLUME] * partialVolume(a[XI], delta_, spacing_) : 0.0;
    }
  }
  prepareBonds(ctx, volume);
}

bool PeriModel::cutByNotch(const double* a, const double* b) const {
  // Proper crossing of segments ab and cd: each one's ends lie strictly on both sides of
  // the other's line (a bond merely touching the notch line is kept).
  auto side = [](const double* p, const double* q, const double* r) {
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
  };
  for (std::size_t k = 0; k + 3 < notch_.size(); k += 4) {
    const double* c = &notch_[k];
    const double* d = &notch_[k + 2];
    if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return true;
  }
  return false;
}

std::vector<double> PeriModel::onGhosts(Context& ctx, const std::vector<double>& owned, int width) {
  std::vector<double> all(ctx.particles.local() * static_cast<std::size_t>(width));
  std::copy(owned.begin(), owned.end(), all.begin());
  ctx.refreshGhosts(all, width);
  return all;
}

// The kernels give accelerations (force densities over the density); damping is viscous,
// a = F/m - damping v; a prescribed axis keeps its initial velocity.
Motion PeriModel::motion() const {
  Motion m;
  m.force = {"ax", "ay", "az"};
  m.perMass = true;
  m.damping = damping_;
  return m;
}

void PeriModel::bodies(const Context& ctx, std::span<Body> owned) const {
  for (std::size_t i = 0; i < owned.size(); ++i) {
    const double* f = ctx.particles.fixed(i);
    owned[i].mass = density_ * f[VOLUME];
    for (int k = 0; k < 3; ++k) {
      owned[i].load[k] = f[FX + k];
      if (f[BCX + k] != 0) owned[i].constraint[k] = Constraint::KeepVelocity;
    }
  }
}

void PeriModel::field(const Context& ctx, int k, std::span<double> out) const {
  const Bonds& B = ctx.bonds;
  if (k == 1) {
    for (std::size_t i = 0; i < out.size(); ++i)
      out[i] = particleEnergy(ctx, i) / ctx.particles.fixed(i)[VOLUME];
    return;
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    const std::size_t n = B.end(i) - B.begin(i);
    std::size_t broken = 0;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) broken += B.attr(b)[WEIGHT] == 0;
    out[i] = n ? static_cast<double>(broken) / static_cast<double>(n) : 0.0;
  }
}

std::vector<std::string> PeriModel::globals() const {
  return {"kinetic", "potential", "broken_bonds"};
}

std::vector<double> PeriModel::globalValues(Context& ctx) {
  const Particles& P = ctx.particles;
  const double kinetic = ctx.sumOwned([&](std::size_t i) {
    const double* x = P.alter(i);
    return 0.5 * density_ * P.fixed(i)[VOLUME] * (x[VX] * x[VX] + x[VY] * x[VY] + x[VZ] * x[VZ]);
  });
  const double broken = ctx.sumOwned([&](std::size_t i) {
    double s = 0;
    for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b)
      s += ctx.bonds.attr(b)[WEIGHT] == 0;
    return s;
  });
  const double elastic = ctx.sumOwned([&](std::size_t i) { return particleEnergy(ctx, i); });
  return {kinetic, elastic, broken / 2};
}

}  // namespace pdq::peri
