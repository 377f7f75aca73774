// The micropolar peridynamic lattice model in 3D (thesis §4.2, §4.4.7–4.4.9), registered as
// "mplm3d": particles on the fcc lattice with six DOFs (u and the orientation's turn),
// interacting with their 12 nearest neighbours as 12 × 12 frame elements and with their 6
// second-nearest through axial springs (models/mplm/3d/elastic_constants.hpp), damaged by
// the laws of §4.3.2 shared with the 2D model, damped by eq. 4.21, reinforced by steel bars,
// and moved by the engine's integrator (velocity Verlet; the orientation a unit quaternion,
// Rotation::Spatial; loads and prescribed values follow the engine's load protocol).
// The force loop's vectors of eight doubles (interaction.hpp) are passed and returned only
// within this file (inlined), never across a library interface: GCC's note that their ABI
// differs with and without AVX does not concern them.
#pragma GCC diagnostic ignored "-Wpsabi"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>

#include "engine/error.hpp"
#include "engine/exact_sum.hpp"
#include "engine/frequency.hpp"
#include "engine/model.hpp"
#include "models/mplm/3d/attributes.hpp"
#include "models/mplm/3d/elastic_constants.hpp"
#include "models/mplm/3d/interaction.hpp"
#include "models/mplm/common/bond_state.hpp"
#include "models/mplm/common/interactions.hpp"
#include "models/mplm/common/lattice.hpp"
#include "models/mplm/common/parameters.hpp"
#include "models/mplm/common/time_step.hpp"

namespace pdq::mplm3d {
namespace {

// Poisson's ratio of the bars, for their torsional stiffness G J = E I/(1+ν).
constexpr double steelPoisson = 0.3;

Vec rowVec(const double* row, int first) { return {row[first], row[first + 1], row[first + 2]}; }

class Mplm3d final : public Model {
 public:
  void configure(const Params& p) override {
    par_.read(p);
    corot_ = par_.kinematics == "corotational";
    surface_ = p.flag("surface_correction", true);
    try {
      k_ = isotropicFcc(par_.E, par_.nu, par_.s);
    } catch (const std::domain_error& e) {
      const auto v = p.raw("poisson_ratio");
      throw InputError(v ? v->file : p.owner(), v ? v->line : 0, e.what());
    }
    par_.setAlphaT(p, alphaFromFractureEnergy(k_, par_.s, par_.fractureEnergy, par_.law.epsT));
  }
  Schema schema() const override { return mplm3d::schema(); }
  double horizon() const override { return par_.horizon(); }
  bool forcesFromBonds() const override { return true; }  // its interactions are bonds

  // Interactions in the reference configuration: concrete–concrete within δ (the 12 nearest
  // and 6 second-nearest neighbours at δ = 1.5 s); steel–steel of the same bar within s; a
  // linking steel particle with concrete within s (not at distance zero).
  void setup(Context& ctx) override {
    if (ctx.dim() != 3)
      throw InputError("mplm3d", 0,
                       "mplm3d needs a 3D problem (particles spread in X, Y and Z); for a 2D "
                       "particle set use mplm2d");
    Particles& P = ctx.particles;
    mplm::addInteractions(ctx, [&](std::size_t i, std::size_t j) {
      if (!interacts(P.fixed(i), P.fixed(j))) return false;
      checkSpacing(P, i, j);
      return true;
    });
    // Generators leave the orientation zero: the reference orientation.
    for (std::size_t i = 0; i < P.owned(); ++i) {
      double* a = P.alter(i);
      if (a[QW] == 0 && a[QX] == 0 && a[QY] == 0 && a[QZ] == 0) a[QW] = 1;
    }
    if (par_.dt > 0) ctx.setDt(par_.dt);
  }

  void prepare(Context& ctx) override {
    mplm::checkDamageRange(ctx, "mplm3d");
    Particles& P = ctx.particles;
    const std::size_t n = P.owned();
    in_.fill(
        P, [&](const double* f) { return massOf(f); },
        [&](const double* f) { return inertiaOf(f); });
    const Bonds& B = ctx.bonds;
    if (B.count() > std::numeric_limits<std::uint32_t>::max())
      throw std::length_error("mplm3d: more than 2^32 interaction ends on one rank");
    // Each owned particle receives the loads of its interactions with partners of smaller
    // ID (the first bonds of its row) in records of its own, after those of the particles
    // before it.
    recvStart_.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t b = B.begin(i);
      while (b < B.end(i) && B.partnerGid(b) < P.gid(i)) ++b;
      recvStart_[i + 1] = recvStart_[i] + static_cast<std::uint32_t>(b - B.begin(i));
    }
    geoOf_.resize(B.count());
    evalStart_.assign(n + 1, 0);
    evals_.clear();
    geo_.clear();
    types_.clear();
    std::map<Stiffness, std::uint32_t> typeOf;
    std::map<Interaction, std::uint32_t> geoIndex;
    auto indexOf = [&](const Interaction& k) {
      const auto [g, fresh] = geoIndex.try_emplace(k, static_cast<std::uint32_t>(geo_.size()));
      if (fresh) geo_.push_back(k);
      return g->second;
    };
    const std::vector<double> surface = surfaceFactors(ctx);
    // Gershgorin bound of the largest eigenvalue of M⁻¹C, C the damping of eq. 4.21.
    double gamma = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double gt = 0, gr = 0;
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        const auto j = static_cast<std::size_t>(B.partner(b));
        Interaction k;
        setReference(k, chord0(P, i, j));
        const Stiffness t = stiffness(P, i, j, k.L0, surface[b]);
        const auto [it, added] = typeOf.try_emplace(t, static_cast<std::uint32_t>(types_.size()));
        if (added) types_.push_back(t);
        k.type = it->second;
        geoOf_[b] = indexOf(k);
        // Evaluated here when i has the smaller ID (the partner's share goes to the owned
        // partner's record, or nowhere for a ghost, whose owner has it from its own
        // evaluation) or the partner is a ghost of smaller ID (from the ghost's end, its
        // share to i's own record).
        const bool first = P.gid(i) < B.partnerGid(b);
        if (first && j < n)
          evals_.push_back(
              {static_cast<std::uint32_t>(b), geoOf_[b], true,
               recvStart_[j] + static_cast<std::uint32_t>(reverse(B, j, P.gid(i)) - B.begin(j))});
        else if (first)
          evals_.push_back({static_cast<std::uint32_t>(b), geoOf_[b], true, noRecord});
        else if (j >= n)
          evals_.push_back({static_cast<std::uint32_t>(b), indexOf(reversed(k)), false,
                            recvStart_[i] + static_cast<std::uint32_t>(b - B.begin(i))});
        gt += 2 * t.c;
        gr += 2 * t.cr;
      }
      evalStart_[i + 1] = static_cast<std::uint32_t>(evals_.size());
      gamma = std::max({gamma, gt / in_.mass[i], gr / in_.inertia[i]});
    }
    unitRows_.resize(geo_.size());
    for (std::size_t g = 0; g < geo_.size(); ++g) unitRows_[g] = unitRows(geo_[g]);
    omegaMax_ = highestFrequency(ctx);
    const double c0 = std::sqrt(par_.E / par_.rho);
    const double thesisDt = par_.s / (std::numbers::pi * c0);
    // Leapfrog with damping γ is stable for Δt < (2/ω)(√(1+ζ²) − ζ), ζ = γ/(2ω); the bound
    // takes the highest frequency and the largest damping together.
    const double zm = ctx.max(gamma) / (2 * omegaMax_);
    const double stable = pdq::stableStep(omegaMax_, zm);
    if (!(par_.dt > 0)) ctx.setDt(par_.dtSafety * stable);
    mplm::reportTimeStep(ctx, "mplm3d", omegaMax_, stable, thesisDt);
  }

  // Each interaction is evaluated once, from its end with the smaller global ID, which
  // gives both its particles their loads (elastic and damping) and both copies of its
  // state; an interaction with a ghost is evaluated alike by the two ranks that hold it (its
  // constants are symmetric in its ends and its reference chord negates exactly). A
  // particle sums the loads of its interactions with larger IDs as it evaluates them, in
  // bond order, then those it received from smaller IDs, in bond order: the same sums on
  // any ranks and threads.
  void force(Context& ctx) override {
    Particles& P = ctx.particles;
    Bonds& B = ctx.bonds;
    if (corot_) {
      evaluate<true>(P, B);  // forms the rotation matrices in its lanes
    } else {
      orientations(P);
      evaluate<false>(P, B);
    }
  }

 private:
  // Particles per block of the force loop: their evaluations' loads are computed together
  // (several interactions at a time in the co-rotational form), then summed in bond order.
  static constexpr long blockParticles = 16;

  template <bool Corot>
  void evaluate(Particles& P, Bonds& B) {
    const long n = static_cast<long>(P.owned());
    recv_.resize(recvStart_.empty() ? 0 : recvStart_.back());
#pragma omp parallel
    {
      std::vector<Lane> lanes;
#pragma omp for schedule(static)
      for (long i0 = 0; i0 < n; i0 += blockParticles) {
        const long i1 = std::min(n, i0 + blockParticles);
        lanes.clear();
        for (long i = i0; i < i1; ++i) {
          double* F = P.integ(i);
          for (int d = 0; d < 3; ++d) F[FORCE_X + d] = F[MOMENT_X + d] = 0;
          for (std::size_t e = evalStart_[i]; e < evalStart_[i + 1]; ++e) {
            const Eval& v = evals_[e];
            const auto j = static_cast<std::uint32_t>(B.partner(v.bond));
            const auto self = static_cast<std::uint32_t>(i);
            if (v.first)
              lanes.push_back({self, j, v.geo, v.target, B.attr(v.bond), F});
            else
              lanes.push_back({j, self, v.geo, v.target, B.attr(v.bond), nullptr});
          }
        }
        if constexpr (Corot)
          corotLoads(P, B, lanes.data(), lanes.size());
        else
          for (const Lane& l : lanes) {
            double before[N_BOND];
            std::copy_n(l.state, N_BOND, before);
            const Loads q = smallLoads(P, geo_[l.geo], l.lo, l.hi, l.state);
            deliver(B, l, q.f.data(), q.mi.data(), q.mj.data(), changed(before, l.state));
          }
      }
    }
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      double* F = P.integ(i);
      for (std::uint32_t r = recvStart_[i]; r < recvStart_[i + 1]; ++r)
        for (int d = 0; d < 3; ++d) {
          F[FORCE_X + d] += recv_[r].f[d];
          F[MOMENT_X + d] += recv_[r].m[d];
        }
    }
  }

 public:
  // Translations and the orientation (a unit quaternion) with the angular velocity in the
  // global frame; supports, bearings and loads from the particle's constraint bits and its
  // load and displacement columns.
  Motion motion() const override {
    Motion m;
    m.rotation = Rotation::Spatial;
    m.orientation = {"qw", "qx", "qy", "qz"};
    m.angularVelocity = {"wx", "wy", "wz"};
    m.moment = {"mx", "my", "mz"};
    m.damping = par_.viscous;
    return m;
  }
  void bodies(const Context& ctx, std::span<Body> owned) const override {
    constexpr int bit[6] = {FIX_X, FIX_Y, FIX_Z, FIX_RX, FIX_RY, FIX_RZ};
    in_.bodies(ctx.particles, owned, bit, LOAD_X, DISP_X, REST_Y, FIX_Y);
  }

  // The stiffness at the reference configuration: each interaction's small-form matrix (the
  // co-rotational form's tangent there) after its damage, the axial term the mean of the
  // pulled and the pushed one (the larger in the bound); a bar's axial term where its plastic
  // strain leaves it elastic there, and in the co-rotational form the geometric term of the
  // axial force that plastic strain leaves.
  bool statesStiffness() const override { return true; }
  void referenceStiffness(const Context& ctx, const StiffnessBlocks& add) const override {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    // Per particle of the row: its own block and each interaction's, the mean then the bound.
    constexpr std::size_t kPair = 72;
    std::vector<double> own(kPair), blocks;
    for (std::size_t i = 0; i < P.owned(); ++i) {
      blocks.assign(kPair * (B.end(i) - B.begin(i)), 0.0);
      std::fill(own.begin(), own.end(), 0.0);
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        const Interaction& g = geo_[geoOf_[b]];
        const Stiffness& t = types_[g.type];
        const Keeps keep = referenceKeeps(t, g, B.attr(b));
        const UnitRows& u = unitRows_[geoOf_[b]];
        double* ij = &blocks[kPair * (b - B.begin(i))];
        for (int r = 0; r < 6; ++r)
          for (int c = 0; c < 12; ++c) {
            const int at = 12 * r + c;
            const double rest = keep.bend * (t.kb * u.bend[at] + t.kt * u.twist[at]);
            const double axial = t.ka * u.axial[at];
            double* to = c < 6 ? &own[6 * r + c] : &ij[6 * r + c - 6];
            to[0] += keep.axial * axial + rest;
            to[36] += keep.axialBound * axial + rest;
          }
        // f_i = N e1 turns with the chord: ∂f_i/∂u_j = (N/d)(I − n0 n0ᵀ).
        for (int p = 0; p < 3 && keep.force != 0; ++p)
          for (int q = 0; q < 3; ++q) {
            const double v = keep.force * g.invL0 * ((p == q ? 1.0 : 0.0) - g.n0[p] * g.n0[q]);
            for (const std::size_t half : {std::size_t{0}, std::size_t{36}}) {
              own[half + 6 * p + q] += v;
              ij[half + 6 * p + q] -= v;
            }
          }
      }
      auto pair = [](const double* k) {
        return std::pair{std::span<const double>(k, 36), std::span<const double>(k + 36, 36)};
      };
      const auto [k, kb] = pair(own.data());
      add(i, i, k, kb);
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        const auto [kj, kbj] = pair(&blocks[kPair * (b - B.begin(i))]);
        add(i, static_cast<std::size_t>(B.partner(b)), kj, kbj);
      }
    }
  }

  std::vector<std::string> fields() const override {
    return {"damage", "omega_t", "omega_c", "ux",  "uy",  "uz",  "rx", "ry",
            "rz",     "sxx",     "syy",     "szz", "syz", "sxz", "sxy"};
  }
  void field(const Context& ctx, int k, std::span<double> out) const override {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    if (k >= 9) orientations(P);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const double* a = P.alter(i);
      const double* X = P.fixed(i);
      double v = 0;
      if (k <= 2) {
        for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
          const double* s = B.attr(b);
          v = std::max(v, k == 0 ? std::max(s[OMEGA_T], s[OMEGA_C]) : s[k - 1]);
        }
      } else if (k <= 5) {
        v = a[AX + k - 3] - X[FX_X + k - 3];
      } else if (k <= 8) {
        v = logRot(orientation(a))[k - 6];
      } else {
        v = stress(ctx, i)[k - 9];
      }
      out[i] = v;
    }
  }

  StrengthSpec strengthSpec() override {
    return {"load_factor", {"ux", "uy", "uz"}, "broken", [this](Context& ctx) {
              return failureMode(ctx);
            }};
  }

  std::vector<std::string> globals() const override {
    return {"load_factor", "load_x",     "load_y",     "load_z",  "ux",      "uy",     "uz",
            "reaction_x",  "reaction_y", "reaction_z", "kinetic", "damaged", "broken", "potential"};
  }
  std::vector<double> globalValues(Context& ctx) override {
    const Particles& P = ctx.particles;
    const double lf = ctx.loadFactor();
    auto sum = [&](auto f) { return ctx.sumOwned(f); };
    const double nMon = sum([&](std::size_t i) { return P.fixed(i)[MONITOR]; });
    const double mean = nMon > 0 ? 1 / nMon : 0.0;
    auto monitored = [&](std::size_t i, double v) { return P.fixed(i)[MONITOR] != 0 ? v : 0.0; };
    std::vector<double> out{lf};
    for (int d = 0; d < 3; ++d)
      out.push_back(lf * sum([&](std::size_t i) { return P.fixed(i)[LOAD_X + d]; }));
    for (int d = 0; d < 3; ++d)
      out.push_back(mean * sum([&](std::size_t i) {
                      return monitored(i, P.alter(i)[AX + d] - P.fixed(i)[FX_X + d]);
                    }));
    // A resting particle is pushed by its support while it sits on it.
    for (int d = 0; d < 3; ++d)
      out.push_back(sum([&](std::size_t i) {
        const bool resting = d == 1 && (in_.constraint[i] & REST_Y) &&
                             P.alter(i)[AY] <= P.fixed(i)[FX_Y] && P.integ(i)[FORCE_Y] < 0;
        return (in_.constraint[i] & (1 << d)) || resting ? monitored(i, -P.integ(i)[FORCE_X + d])
                                                         : 0.0;
      }));
    out.push_back(sum([&](std::size_t i) {
      const double* a = P.alter(i);
      return 0.5 * in_.mass[i] * (a[VX] * a[VX] + a[VY] * a[VY] + a[VZ] * a[VZ]) +
             0.5 * in_.inertia[i] * (a[WX] * a[WX] + a[WY] * a[WY] + a[WZ] * a[WZ]);
    }));
    out.push_back(mplm::damagedInteractions(ctx, std::numeric_limits<double>::min()));
    out.push_back(mplm::damagedInteractions(ctx, 1.0));
    out.push_back(potential(ctx));
    return out;
  }

 private:
  double massOf(const double* f) const {
    return isSteel(f) ? par_.steelMass(f[AREA])
                      : par_.rho * par_.s * par_.s * par_.s / std::sqrt(2.0);
  }
  double inertiaOf(const double* f) const { return par_.inertia(massOf(f), isSteel(f)); }
  static double distance(const double* fi, const double* fj) {
    const double dx = fj[FX_X] - fi[FX_X], dy = fj[FX_Y] - fi[FX_Y], dz = fj[FX_Z] - fi[FX_Z];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  // Concrete neighbours must sit at s or √2 s: masses and stiffnesses are those of the
  // fcc lattice at the model's spacing.
  void checkSpacing(const Particles& P, std::size_t i, std::size_t j) const {
    const double *fi = P.fixed(i), *fj = P.fixed(j);
    if (isSteel(fi) || isSteel(fj)) return;
    const double d = distance(fi, fj), s = par_.s;
    if (std::fabs(d - s) > 1e-3 * s && std::fabs(d - std::sqrt(2.0) * s) > 1e-3 * s) {
      std::ostringstream why;
      why << "concrete particles " << P.gid(i) << " and " << P.gid(j) << " are " << d
          << " apart, but the model's fcc lattice at spacing " << s
          << " has neighbours at s and sqrt(2) s only: set [model] spacing to the particles' "
             "spacing";
      throw InputError("mplm3d", 0, why.str());
    }
  }

  bool interacts(const double* fi, const double* fj) const {
    auto end = [](const double* f) { return mplm::End{isSteel(f), f[BAR], f[LINK] != 0}; };
    return mplm::interacts(end(fi), end(fj), distance(fi, fj), par_.horizon(), par_.s);
  }

  // Surface correction: a particle on a free face lacks the concrete interactions whose
  // partners would lie outside the body. Under a uniform strain a missing interaction along
  // −r carries what the one along +r carries (the lattice is centrosymmetric), so the
  // interaction i→i+r takes over the half of the missing i→i−r that belongs to i's cell.
  // Per concrete interaction ij (chord r): 1 + ½ if i has no partner at −r, + ½ if j has
  // none at +r; every particle's cell then stores the continuum's energy under any uniform
  // strain, and the lattice is the body its particle volumes s³/√2 fill. 1 for steel.
  std::vector<double> surfaceFactors(Context& ctx) const {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    std::vector<double> factor(B.count(), 1.0);
    if (!surface_) return factor;
    auto concrete = [&](std::size_t i, std::size_t b) {
      return !isSteel(P.fixed(i)) && !isSteel(P.fixed(static_cast<std::size_t>(B.partner(b))));
    };
    auto chord = [&](std::size_t i, std::size_t b) {
      const double *fi = P.fixed(i), *fj = P.fixed(static_cast<std::size_t>(B.partner(b)));
      return Vec{fj[FX_X] - fi[FX_X], fj[FX_Y] - fi[FX_Y], fj[FX_Z] - fi[FX_Z]};
    };
    // Per local particle, the IDs of the partners whose interaction has no opposite one
    // (−1 pads); ghosts get theirs from their owners.
    constexpr int width = 18;  // interactions of an fcc particle
    std::vector<double> open(width * P.local(), -1.0);
    const double tol = 1e-6 * par_.s;
    for (std::size_t i = 0; i < P.owned(); ++i) {
      int k = 0;
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        if (!concrete(i, b)) continue;
        const Vec r = chord(i, b);
        bool opposite = false;
        for (std::size_t c = B.begin(i); c < B.end(i) && !opposite; ++c) {
          if (c == b || !concrete(i, c)) continue;
          const Vec q = chord(i, c);
          opposite = std::fabs(r[0] + q[0]) < tol && std::fabs(r[1] + q[1]) < tol &&
                     std::fabs(r[2] + q[2]) < tol;
        }
        if (!opposite && k < width) open[width * i + k++] = static_cast<double>(B.partnerGid(b));
      }
    }
    ctx.refreshGhosts(open, width);
    auto lacks = [&](std::size_t i, Gid partner) {
      const double* row = &open[width * i];
      return std::find(row, row + width, static_cast<double>(partner)) != row + width;
    };
    for (std::size_t i = 0; i < P.owned(); ++i)
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        if (!concrete(i, b)) continue;
        const auto j = static_cast<std::size_t>(B.partner(b));
        factor[b] = 1 + 0.5 * lacks(i, B.partnerGid(b)) + 0.5 * lacks(j, P.gid(i));
      }
    return factor;
  }

  // The reference chord X_j − X_i.
  static Vec chord0(const Particles& P, std::size_t i, std::size_t j) {
    const double *fi = P.fixed(i), *fj = P.fixed(j);
    return {fj[FX_X] - fi[FX_X], fj[FX_Y] - fi[FX_Y], fj[FX_Z] - fi[FX_Z]};
  }

  Stiffness stiffness(const Particles& P, std::size_t i, std::size_t j, double L,
                      double surface) const {
    const double* fi = P.fixed(i);
    const double* fj = P.fixed(j);
    Stiffness k;
    const double s = par_.s;
    k.kind = mplm::kindOf(isSteel(fi), isSteel(fj), par_.damage);
    if (k.kind == Kind::Bar) {
      k.ka = par_.steelE * fi[AREA] / L;
      k.kb = par_.steelE * fi[SECOND_MOMENT] / L;
      k.kt = k.kb / (1 + steelPoisson);
      k.epsY = par_.steelYield;
    } else if (isSteel(fi) || isSteel(fj)) {
      k.ka = mplm::linkAxial(par_.link, k_.a, s, L);
      k.kb = mplm::linkBending(par_.link, k_.b, s, L);
      k.kt = mplm::linkBending(par_.link, k_.c, s, L);
    } else {
      const bool nearest = L < 1.2 * s;  // else second nearest, at √2 s: axial only
      k.ka = surface * (nearest ? k_.a : k_.a2) / L;
      k.kb = nearest ? surface * k_.b / L : 0.0;
      k.kt = nearest ? surface * k_.c / L : 0.0;
    }
    k.c = mplm::dampingCoefficient(par_.zeta, k.ka, massOf(fi), massOf(fj));
    k.cr = mplm::dampingCoefficient(par_.zetaRotation, 4 * k.kb, inertiaOf(fi), inertiaOf(fj));
    return k;
  }

  // The elastic load of interaction k (as particle i holds it) on i; the rotation
  // matrices or vectors come from orientations(), which the caller runs first.
  EndLoad load(const Particles& P, const Interaction& k, std::size_t i, std::size_t j,
               double* state, bool update) const {
    return elasticForce(k, types_[k.type], chord(P, k, i, j), par_.law, state, update);
  }
  // The loads of interaction k (as i holds it) on both ends with eq. 4.21's damping after
  // damage, updating its state: the force on i (j's is its opposite) and the two moments.
  struct Loads {
    Vec f, mi, mj;
  };
  // A load received from a partner of smaller ID.
  struct Received {
    Vec f, m;
  };
  // Adds eq. 4.21's damping (c, cr: after damage) from the ends' velocities and angular
  // velocities (rows of alterable attributes) to the elastic loads f, mi, mj.
  template <class T, class RowI, class RowJ>
  static void damp(T c, T cr, const RowI& ai, const RowJ& aj, T f[3], T mi[3], T mj[3]) {
    for (int d = 0; d < 3; ++d) {
      const T dw = cr * (aj(WX + d) - ai(WX + d));
      f[d] = f[d] + c * (aj(VX + d) - ai(VX + d));
      mi[d] = mi[d] + dw;
      mj[d] = mj[d] - dw;
    }
  }
  // The small form's loads of interaction k (as i holds it) on both ends with damping after
  // damage, updating its state: the force on i (j's is its opposite) and the two moments.
  Loads smallLoads(const Particles& P, const Interaction& k, std::size_t i, std::size_t j,
                   double* state) const {
    const Stiffness& t = types_[k.type];
    Loads l;
    EndLoad e = elasticForce(k, t, chordOf<false>(P, k, i, j), par_.law, state, true, &l.mj);
    const double *a = P.alter(i), *aj = P.alter(j);
    damp<double>(
        e.keep * t.c, e.keep * t.cr, [&](int q) { return a[q]; }, [&](int q) { return aj[q]; },
        e.f.data(), e.m.data(), l.mj.data());
    l.f = e.f;
    l.mi = e.m;
    return l;
  }

  // One evaluation of an interaction: from particle lo to hi (lo has the smaller ID), its
  // geometry as lo holds it, the record that receives hi's share (noRecord: a ghost hi's),
  // its state, and lo's force and moment (null: a ghost lo).
  struct Lane {
    std::uint32_t lo, hi, geo, target;
    double* state;
    double* sum;
  };
  // Whether an evaluation changed the interaction's state (bit for bit).
  static bool changed(const double* before, const double* state) {
    return std::memcmp(before, state, N_BOND * sizeof(double)) != 0;
  }
  // Takes an evaluation's loads to their particles, in the order of the lanes: lo's sums
  // are added to in its bond order. An owned hi's copy of the state is written only when
  // the evaluation changed it (both copies are equal before: set up alike, saved, restored
  // and migrated together).
  void deliver(Bonds& B, const Lane& l, const double* f, const double* mi, const double* mj,
               bool stateChanged) {
    if (l.sum)
      for (int d = 0; d < 3; ++d) {
        l.sum[FORCE_X + d] += f[d];
        l.sum[MOMENT_X + d] += mi[d];
      }
    if (l.target == noRecord) return;
    recv_[l.target] = {{-f[0], -f[1], -f[2]}, {mj[0], mj[1], mj[2]}};
    if (l.sum && stateChanged) {
      double* copy = B.attr(B.begin(l.hi) + (l.target - recvStart_[l.hi]));
      for (int k = 0; k < N_BOND; ++k) copy[k] = l.state[k];
    }
  }
  // Interactions evaluated side by side, one per lane: lane-wise the scalar form's operations
  // in the same order (interaction.hpp), so the same bits.
  static constexpr int width = 8;
  using Wide = double __attribute__((vector_size(width * sizeof(double))));

  // The co-rotational loads of `count` evaluations, `width` at a time, delivered; with AVX-512
  // or AVX2 where the processor has it (no FMA: the same roundings as without).
  [[gnu::flatten, gnu::target_clones("arch=x86-64-v4", "avx2", "default")]] void corotLoads(
      const Particles& P, Bonds& B, const Lane* lanes, std::size_t count) {
    for (std::size_t s = 0; s < count; s += width) {
      const Lane* ln[width];
      const double *ai[width], *aj[width];
      const Interaction* g[width];
      const Stiffness* t[width];
      for (int k = 0; k < width; ++k) {
        ln[k] = &lanes[std::min(s + k, count - 1)];  // the last one again past the end
        ai[k] = P.alter(ln[k]->lo);
        aj[k] = P.alter(ln[k]->hi);
        g[k] = &geo_[ln[k]->geo];
        t[k] = &types_[g[k]->type];
      }
      auto wide = [](auto get) {
        return Wide{get(0), get(1), get(2), get(3), get(4), get(5), get(6), get(7)};
      };
      Wide r[3], e2[3], e3[3], RiW[9], RjW[9];
      for (int c = 0; c < 3; ++c) {
        r[c] = wide([&](int k) { return aj[k][AX + c] - ai[k][AX + c]; });
        e2[c] = wide([&](int k) { return g[k]->e2[c]; });
        e3[c] = wide([&](int k) { return g[k]->e3[c]; });
      }
      // The rotation matrices from the orientations, lane by lane as orientations() forms
      // them (the same bits): four gathered doubles a particle instead of nine.
      auto quat = [&](const double* const* a, int c) {
        return wide([&](int k) { return a[k][c]; });
      };
      rotationEntries(quat(ai, QW), quat(ai, QX), quat(ai, QY), quat(ai, QZ), RiW);
      rotationEntries(quat(aj, QW), quat(aj, QX), quat(aj, QY), quat(aj, QZ), RjW);
      const Wide L0 = wide([&](int k) { return g[k]->L0; });
      const Wide invL0 = wide([&](int k) { return g[k]->invL0; });
      Wide da, invL, ti[3], tj[3];
      Frame<Wide> fr;
      corotMeasures<Wide>(r, RiW, RjW, e2, e3, L0, da, invL, ti, tj, fr);
      const Wide epsA = da * invL0;  // eq. 4.7
      const Wide curv = par_.law.beta * curvature<Wide>(ti, tj);
      Wide axialKeep, bendKeep, stretch;
      bool stateChanged[width];
      for (int k = 0; k < width; ++k) {
        double before[N_BOND];
        std::copy_n(ln[k]->state, N_BOND, before);
        const mplm::Held h = damageStep(*t[k], par_.law, epsA[k], curv[k], da[k], g[k]->L0,
                                        ln[k]->state, s + k < count);
        stateChanged[k] = changed(before, ln[k]->state);
        axialKeep[k] = h.axialKeep;
        bendKeep[k] = h.bendKeep;
        stretch[k] = h.stretch;
      }
      const Resultants<Wide> q = resultants<Wide>(
          wide([&](int k) { return t[k]->ka; }), wide([&](int k) { return t[k]->kb; }),
          wide([&](int k) { return t[k]->kt; }), stretch, axialKeep, bendKeep, ti, tj);
      Wide f[3], mi[3], mj[3];
      corotLoad<Wide>(fr, invL, q, f, mi, mj);
      damp<Wide>(
          axialKeep * wide([&](int k) { return t[k]->c; }),
          axialKeep * wide([&](int k) { return t[k]->cr; }),
          [&](int col) { return wide([&](int k) { return ai[k][col]; }); },
          [&](int col) { return wide([&](int k) { return aj[k][col]; }); }, f, mi, mj);
      for (int k = 0; k < width && s + k < count; ++k) {
        const double fk[3] = {f[0][k], f[1][k], f[2][k]};
        const double mik[3] = {mi[0][k], mi[1][k], mi[2][k]};
        const double mjk[3] = {mj[0][k], mj[1][k], mj[2][k]};
        deliver(B, *ln[k], fk, mik, mjk, stateChanged[k]);
      }
    }
  }

  // The bond of owned particle j whose partner is gid (bonds are sorted by partner ID).
  static std::size_t reverse(const Bonds& B, std::size_t j, Gid gid) {
    std::size_t lo = B.begin(j), hi = B.end(j);
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (B.partnerGid(mid) < gid)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo;
  }
  Chord chord(const Particles& P, const Interaction& k, std::size_t i, std::size_t j) const {
    return corot_ ? chordOf<true>(P, k, i, j) : chordOf<false>(P, k, i, j);
  }
  template <bool Corot>
  Chord chordOf(const Particles& P, const Interaction& k, std::size_t i, std::size_t j) const {
    const double *a = P.alter(i), *aj = P.alter(j);
    const Vec r{aj[AX] - a[AX], aj[AY] - a[AY], aj[AZ] - a[AZ]};
    if constexpr (Corot) {
      return corotChord(k, r, rot_[i], rot_[j]);
    } else {
      const Vec r0 = chord0(P, i, j);
      const Vec d{r[0] - r0[0], r[1] - r0[1], r[2] - r0[2]};
      return smallChord(k, d, th_[i], th_[j]);
    }
  }

  // The strain energy of the lattice at its current damage (each interaction is held by
  // both of its particles: half on each). Its gradient is minus the elastic forces and
  // moments of force() (moments: with respect to global turns of the orientations).
  double potential(const Context& ctx) const {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    orientations(P);
    return ctx.sumOwned([&](std::size_t i) {
      double e = 0;
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        const Interaction& k = geo_[geoOf_[b]];
        const auto j = static_cast<std::size_t>(B.partner(b));
        e += 0.5 * elasticEnergy(k, types_[k.type], chord(P, k, i, j), par_.law, B.attr(b));
      }
      return e;
    });
  }

  static Quat orientation(const double* a) { return {a[QW], a[QX], a[QY], a[QZ]}; }

  // An interaction end's rows of its 12 × 12 small-form matrix (u, θ of i, then of j),
  // −∂(f_i, m_i)/∂(u_i, θ_i, u_j, θ_j) row by row, for unit axial, bending and torsional
  // constants: its stiffness is a sum of the three, scaled.
  struct UnitRows {
    std::array<double, 72> axial, bend, twist;
  };
  UnitRows unitRows(const Interaction& g) const {
    UnitRows u;
    Stiffness unit[3];
    unit[0].ka = unit[1].kb = unit[2].kt = 1;
    std::array<double, 72>* rows[3] = {&u.axial, &u.bend, &u.twist};
    for (int c = 0; c < 12; ++c) {
      double x[12] = {};
      x[c] = 1;
      const Vec d{x[6] - x[0], x[7] - x[1], x[8] - x[2]};
      const Chord ch = smallChord(g, d, rowVec(x, 3), rowVec(x, 9));
      for (int k = 0; k < 3; ++k) {
        const EndLoad e = elasticForce(g, unit[k], ch, par_.law, nullptr, false);
        for (int r = 0; r < 3; ++r) {
          (*rows[k])[12 * r + c] = -e.f[r];
          (*rows[k])[12 * (r + 3) + c] = -e.m[r];
        }
      }
    }
    return u;
  }
  // What an interaction keeps at the reference configuration in its state: the factors of
  // its axial and its bending and torsional terms, and the axial force a bar's plastic
  // strain leaves there (co-rotational form; 0 otherwise).
  struct Keeps {
    double axial = 1, axialBound = 1, bend = 1, force = 0;
  };
  Keeps referenceKeeps(const Stiffness& t, const Interaction& g, const double* state) const {
    Keeps k;
    if (t.kind == Kind::Concrete) {
      k.bend = 1 - std::max(state[OMEGA_T], state[OMEGA_C]);  // and the pulled side's axial
      const double pushed = par_.law.crushing ? 1 - state[OMEGA_C] : 1.0;
      k.axial = 0.5 * (k.bend + pushed);
      k.axialBound = std::max(k.bend, pushed);
    } else if (t.kind == Kind::Bar) {
      // Beyond the yield strain it yields either way; at it, one way.
      const double p = std::fabs(state[PLASTIC]);
      k.axial = p < t.epsY ? 1.0 : (p > t.epsY ? 0.0 : 0.5);
      k.axialBound = p <= t.epsY ? 1.0 : 0.0;
      if (corot_) k.force = -t.ka * mplm::plasticStrain(0, state[PLASTIC], t.epsY) * g.L0;
    }
    return k;
  }

  // Each local particle's (owned and ghosts) rotation matrix in the co-rotational form, its
  // rotation vector θ = log q in the small form: before the scalar uses of chord() (the
  // potential, the stresses) and the small form's force loop.
  void orientations(const Particles& P) const {
    const long nl = static_cast<long>(P.local());
    if (corot_) {
      rot_.resize(P.local());
#pragma omp parallel for schedule(static)
      for (long i = 0; i < nl; ++i) rot_[i] = rotationMatrix(orientation(P.alter(i)));
    } else {
      th_.resize(P.local());
#pragma omp parallel for schedule(static)
      for (long i = 0; i < nl; ++i) th_[i] = logRot(orientation(P.alter(i)));
    }
  }

  // ω_max of the undamaged lattice in small deformation, six DOFs per particle.
  double highestFrequency(Context& ctx) const {
    const std::size_t n = ctx.particles.owned();
    pdq::DofSystem sys;
    sys.dofs = 6;
    sys.mass.resize(6 * n);
    sys.held.resize(6 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < 6; ++d) {
        sys.mass[6 * i + d] = d < 3 ? in_.mass[i] : in_.inertia[i];
        sys.held[6 * i + d] = (in_.constraint[i] & (1 << d)) != 0;
      }
    auto restoring = [&](std::span<const double> u, std::span<double> f) {
      for (std::size_t i = 0; i < n; ++i) {
        double sum[6] = {0, 0, 0, 0, 0, 0};
        const double* ui = &u[6 * i];
        for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b) {
          const Interaction& k = geo_[geoOf_[b]];
          const double* uj = &u[6 * static_cast<std::size_t>(ctx.bonds.partner(b))];
          const Vec d{uj[0] - ui[0], uj[1] - ui[1], uj[2] - ui[2]};
          const EndLoad e =
              elasticForce(k, types_[k.type], smallChord(k, d, rowVec(ui, 3), rowVec(uj, 3)),
                           mplm::DamageLaw{}, nullptr, false);
          for (int c = 0; c < 3; ++c) {
            sum[c] += e.f[c];
            sum[3 + c] += e.m[c];
          }
        }
        std::copy_n(sum, 6, &f[6 * i]);
      }
    };
    return pdq::highestFrequency(ctx, sys, restoring, par_.powerIterations);
  }

  std::string failureMode(Context& ctx) const {
    const Particles& P = ctx.particles;
    return mplm::failureMode(ctx, in_.constraint, [&](std::size_t i) { return &P.alter(i)[AX]; });
  }

  // Virial stress of particle i from its elastic interactions (no damping), with the
  // orientations of the co-rotational form up to date:
  // σ = (1/2ΔV) Σ_j r_ij ⊗ f_ij, symmetrised, ΔV = s³/√2 (a bar's A_s s); order xx, yy, zz,
  // yz, xz, xy.
  std::array<double, 6> stress(const Context& ctx, std::size_t i) const {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    const double* a = P.alter(i);
    double s[3][3] = {};
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const Interaction& k = geo_[geoOf_[b]];
      const auto j = static_cast<std::size_t>(B.partner(b));
      const double* aj = P.alter(j);
      double state[N_BOND];
      std::copy_n(B.attr(b), N_BOND, state);
      const EndLoad e = load(P, k, i, j, state, false);
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) s[p][q] += (aj[AX + p] - a[AX + p]) * e.f[q];
    }
    const double V =
        isSteel(P.fixed(i)) ? P.fixed(i)[AREA] * par_.s : par_.s * par_.s * par_.s / std::sqrt(2.0);
    const double k = 1 / (2 * V);
    return {k * s[0][0],
            k * s[1][1],
            k * s[2][2],
            0.5 * k * (s[1][2] + s[2][1]),
            0.5 * k * (s[0][2] + s[2][0]),
            0.5 * k * (s[0][1] + s[1][0])};
  }

  mplm::Parameters par_;
  bool corot_ = true;    // kinematics = "corotational"
  bool surface_ = true;  // surface_correction
  ElasticConstants k_;
  std::vector<Interaction> geo_;      // the distinct geometries of the interaction ends
  std::vector<Stiffness> types_;      // the distinct constants of the interactions
  std::vector<std::uint32_t> geoOf_;  // per bond (same index as ctx.bonds): its geometry
  std::vector<UnitRows> unitRows_;    // per geometry
  // The interactions a particle evaluates, evals_[evalStart_[i]] to evals_[evalStart_[i + 1]]
  // in bond order: its bond, the geometry as the end of smaller ID holds it, whether the
  // particle is that end, and the record that receives the share of the end of larger ID
  // (noRecord: a ghost's).
  struct Eval {
    std::uint32_t bond, geo : 31, first : 1, target;
  };
  static constexpr std::uint32_t noRecord = std::numeric_limits<std::uint32_t>::max();
  std::vector<Eval> evals_;
  std::vector<std::uint32_t> evalStart_;
  // Per owned particle: its records of loads from partners of smaller ID, from
  // recvStart_[i] to recvStart_[i + 1], in bond order.
  std::vector<std::uint32_t> recvStart_;
  std::vector<Received> recv_;
  mutable std::vector<Mat> rot_;  // rotation matrix per local particle (co-rotational form)
  mutable std::vector<Vec> th_;   // rotation vector per local particle (small form)
  mplm::Inertia in_;
  double omegaMax_ = 0;
};

PDQ_REGISTER_MODEL(Mplm3d, "mplm3d",
                   "micropolar peridynamic lattice model, 3D fcc: six DOFs, concrete with damage, "
                   "steel bars");

}  // namespace
}  // namespace pdq::mplm3d
