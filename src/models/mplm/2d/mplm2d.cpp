// The micropolar peridynamic lattice model in 2D (thesis chapter 4), registered as
// "mplm2d": particles on a hexagonal lattice with DOFs u_x, u_y, θ_z, interacting with
// their six nearest neighbours through the beam-like stiffness of eq. 4.3, damaged by the
// laws of §4.3.2, damped by eq. 4.21, reinforced by steel bars (§4.3.4), and moved by the
// engine's integrator (velocity Verlet; loads and prescribed displacements follow the
// engine's load protocol: a linear ramp, then held, §4.4).
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numbers>
#include <sstream>

#include "engine/error.hpp"
#include "engine/frequency.hpp"
#include "engine/model.hpp"
#include "models/mplm/2d/attributes.hpp"
#include "models/mplm/2d/interaction.hpp"
#include "models/mplm/2d/parameters.hpp"
#include "models/mplm/common/bond_state.hpp"
#include "models/mplm/common/lattice.hpp"
#include "models/mplm/common/time_step.hpp"

namespace pdq::mplm {
namespace {

class Mplm2d final : public Model {
 public:
  void configure(const Params& p) override { par_.read(p); }
  Schema schema() const override { return mplm::schema(); }
  double horizon() const override { return par_.horizon(); }
  bool forcesFromBonds() const override { return true; }  // its interactions are bonds

  // Interactions in the reference configuration: concrete–concrete within δ; steel–steel
  // of the same bar within s; a linking steel particle with concrete within s (not at
  // distance zero). Concrete neighbours must sit at the model's spacing: masses and
  // stiffnesses are those of a lattice at s.
  void setup(Context& ctx) override {
    if (ctx.dim() != 2) throw InputError("mplm2d", 0, "mplm2d needs a 2D problem (all Z equal)");
    const Particles& P = ctx.particles;
    addInteractions(ctx, [&](std::size_t i, std::size_t j) {
      if (!interacts(P.fixed(i), P.fixed(j))) return false;
      checkSpacing(P, i, j);
      return true;
    });
    if (par_.dt > 0) ctx.setDt(par_.dt);
  }

  void prepare(Context& ctx) override {
    mplm::checkDamageRange(ctx, "mplm2d");
    Particles& P = ctx.particles;
    const std::size_t n = P.owned();
    in_.fill(
        P, [&](const double* f) { return massOf(f); },
        [&](const double* f) { return inertiaOf(f); });
    inter_.resize(ctx.bonds.count());
    double omegaBond = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b) {
        inter_[b] = makeInteraction(P, i, static_cast<std::size_t>(ctx.bonds.partner(b)));
        omegaBond = std::max(omegaBond, std::sqrt(inter_[b].ka / massOf(P.fixed(i))));
      }
    omegaMax_ = highestFrequency(ctx);
    const double c0 = std::sqrt(par_.E / par_.rho);
    const double thesisDt = par_.s / (std::numbers::pi * c0);
    // A mode at ω_max sees about ζ ω_max / ω_bond of critical damping from eq. 4.21.
    omegaBond = ctx.max(omegaBond);
    const double zm = std::max(par_.zeta, par_.zetaRotation) * omegaMax_ / omegaBond;
    const double stable = stableStep(omegaMax_, zm);
    if (!(par_.dt > 0)) ctx.setDt(par_.dtSafety * stable);
    mplm::reportTimeStep(ctx, "mplm2d", omegaMax_, stable, thesisDt);
  }

  void force(Context& ctx) override {
    Particles& P = ctx.particles;
    Bonds& B = ctx.bonds;
    const bool corot = par_.kinematics == "corotational";
    const long n = static_cast<long>(P.owned());
    if (corot) turnings(P);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) {
      const double* a = P.alter(i);
      double fx = 0, fy = 0, m = 0;
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        const Interaction& k = inter_[b];
        const double* aj = P.alter(k.j);
        const double rx = aj[AX] - a[AX], ry = aj[AY] - a[AY];
        const Chord ch = corot ? corotChord(k, rx, ry, cs_[2 * i], cs_[2 * i + 1], cs_[2 * k.j],
                                            cs_[2 * k.j + 1])
                               : smallChord(k, rx - k.r0x, ry - k.r0y, a[THETA], aj[THETA]);
        const EndLoad e = elasticForce(k, ch, par_.law, B.attr(b), true);
        fx += e.fx + e.keep * k.c * (aj[VX] - a[VX]);
        fy += e.fy + e.keep * k.c * (aj[VY] - a[VY]);
        m += e.m + e.keep * k.cr * (aj[OMEGA] - a[OMEGA]);
      }
      double* F = P.integ(i);
      F[FORCE_X] = fx;
      F[FORCE_Y] = fy;
      F[MOMENT] = m;
    }
  }

  // Translations u_x, u_y and the rotation θ_z; supports, bearings and loads from the
  // particle's constraint bits and its load and displacement columns.
  Motion motion() const override {
    Motion m;
    m.position = {"x", "y"};
    m.velocity = {"vx", "vy"};
    m.force = {"fx", "fy"};
    m.rotation = Rotation::Planar;
    m.orientation = {"theta"};
    m.angularVelocity = {"omega"};
    m.moment = {"mz"};
    m.damping = par_.viscous;
    return m;
  }
  void bodies(const Context& ctx, std::span<Body> owned) const override {
    constexpr int bit[3] = {FIX_X, FIX_Y, FIX_T};
    in_.bodies(ctx.particles, owned, bit, LOAD_X, DISP_X, REST_Y, FIX_Y);
  }

  std::vector<std::string> fields() const override {
    return {"damage", "omega_t", "omega_c", "ux", "uy", "theta", "sxx", "syy", "sxy"};
  }
  void field(const Context& ctx, int k, std::span<double> out) const override {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const double* a = P.alter(i);
      const double* X = P.fixed(i);
      double v = 0;
      switch (k) {
        case 0:
        case 1:
        case 2:
          for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
            const double* s = B.attr(b);
            v = std::max(v, k == 0 ? std::max(s[OMEGA_T], s[OMEGA_C]) : s[k - 1]);
          }
          break;
        case 3:
          v = a[AX] - X[FX_X];
          break;
        case 4:
          v = a[AY] - X[FX_Y];
          break;
        case 5:
          v = a[THETA];
          break;
        default:
          v = stress(ctx, i)[k - 6];
      }
      out[i] = v;
    }
  }

  // pdq strength: the load factor, the monitored displacement and the broken interactions.
  StrengthSpec strengthSpec() override {
    return {
        "load_factor", {"ux", "uy"}, "broken", [this](Context& ctx) { return failureMode(ctx); }};
  }

  std::vector<std::string> globals() const override {
    return {"load_factor", "load_x",  "load_y",  "ux",     "uy",       "reaction_x",
            "reaction_y",  "kinetic", "damaged", "broken", "potential"};
  }
  std::vector<double> globalValues(Context& ctx) override {
    const Particles& P = ctx.particles;
    const double lf = ctx.loadFactor();
    auto sum = [&](auto f) { return ctx.sumOwned(f); };
    const double lx = lf * sum([&](std::size_t i) { return P.fixed(i)[LOAD_X]; });
    const double ly = lf * sum([&](std::size_t i) { return P.fixed(i)[LOAD_Y]; });
    const double nMon = sum([&](std::size_t i) { return P.fixed(i)[MONITOR]; });
    auto monitored = [&](std::size_t i, double v) { return P.fixed(i)[MONITOR] != 0 ? v : 0.0; };
    const double ux =
        sum([&](std::size_t i) { return monitored(i, P.alter(i)[AX] - P.fixed(i)[FX_X]); });
    const double uy =
        sum([&](std::size_t i) { return monitored(i, P.alter(i)[AY] - P.fixed(i)[FX_Y]); });
    // A resting particle is pushed by its support while it sits on it.
    auto reaction = [&](std::size_t i, int d, int bit) {
      const bool resting = d == FORCE_Y && (in_.constraint[i] & REST_Y) &&
                           P.alter(i)[AY] <= P.fixed(i)[FX_Y] && P.integ(i)[d] < 0;
      return (in_.constraint[i] & bit) || resting ? monitored(i, -P.integ(i)[d]) : 0.0;
    };
    const double rx = sum([&](std::size_t i) { return reaction(i, FORCE_X, FIX_X); });
    const double ry = sum([&](std::size_t i) { return reaction(i, FORCE_Y, FIX_Y); });
    const double ke = sum([&](std::size_t i) {
      const double* a = P.alter(i);
      return 0.5 * in_.mass[i] * (a[VX] * a[VX] + a[VY] * a[VY]) +
             0.5 * in_.inertia[i] * a[OMEGA] * a[OMEGA];
    });
    const double mean = nMon > 0 ? 1 / nMon : 0.0;
    return {lf,
            lx,
            ly,
            ux * mean,
            uy * mean,
            rx,
            ry,
            ke,
            damagedInteractions(ctx, std::numeric_limits<double>::min()),
            damagedInteractions(ctx, 1.0),
            potential(ctx)};
  }

 private:
  double massOf(const double* f) const {
    return isSteel(f) ? par_.steelMass(f[AREA]) : par_.concreteMass();
  }
  double inertiaOf(const double* f) const { return par_.inertia(massOf(f), isSteel(f)); }
  void checkSpacing(const Particles& P, std::size_t i, std::size_t j) const {
    const double *fi = P.fixed(i), *fj = P.fixed(j);
    if (isSteel(fi) || isSteel(fj)) return;
    const double d = std::hypot(fj[FX_X] - fi[FX_X], fj[FX_Y] - fi[FX_Y]);
    if (std::fabs(d - par_.s) > 1e-3 * par_.s) {
      std::ostringstream why;
      why << "concrete particles " << P.gid(i) << " and " << P.gid(j) << " are " << d
          << " apart, but the model's lattice spacing is " << par_.s
          << ": set [model] spacing to the particles' spacing";
      throw InputError("mplm2d", 0, why.str());
    }
  }

  bool interacts(const double* fi, const double* fj) const {
    const double dx = fj[FX_X] - fi[FX_X], dy = fj[FX_Y] - fi[FX_Y];
    auto end = [](const double* f) { return End{isSteel(f), f[BAR], f[LINK] != 0}; };
    return mplm::interacts(end(fi), end(fj), std::sqrt(dx * dx + dy * dy), par_.horizon(), par_.s);
  }

  Interaction makeInteraction(const Particles& P, std::size_t i, std::size_t j) const {
    const double* fi = P.fixed(i);
    const double* fj = P.fixed(j);
    Interaction k;
    k.j = static_cast<std::int32_t>(j);
    k.r0x = fj[FX_X] - fi[FX_X];
    k.r0y = fj[FX_Y] - fi[FX_Y];
    k.L0 = std::sqrt(k.r0x * k.r0x + k.r0y * k.r0y);
    k.invL0 = 1 / k.L0;
    k.n0x = k.r0x / k.L0;
    k.n0y = k.r0y / k.L0;
    const bool si = isSteel(fi), sj = isSteel(fj);
    const double a = par_.concrete.a, b = par_.concrete.b, s = par_.s, L = k.L0;
    k.kind = kindOf(si, sj, par_.damage);
    if (k.kind == Kind::Bar) {
      k.ka = par_.steelE * fi[AREA] / L;
      k.kb = par_.steelE * fi[SECOND_MOMENT] / L;
      k.epsY = par_.steelYield;
    } else if (si || sj) {
      k.ka = linkAxial(par_.link, a, s, L);
      k.kb = linkBending(par_.link, b, s, L);
    } else {
      k.ka = a / L;
      k.kb = b / L;
    }
    // Eq. 4.21 for translation (stiffness a/d) and rotation (4b/d: moment per end rotation).
    k.c = dampingCoefficient(par_.zeta, k.ka, massOf(fi), massOf(fj));
    k.cr = dampingCoefficient(par_.zetaRotation, 4 * k.kb, inertiaOf(fi), inertiaOf(fj));
    return k;
  }

  // The strain energy of the lattice at its current damage (each interaction is held by
  // both of its particles: half on each).
  double potential(const Context& ctx) const {
    const Bonds& B = ctx.bonds;
    return ctx.sumOwned([&](std::size_t i) {
      double e = 0;
      for (std::size_t b = B.begin(i); b < B.end(i); ++b)
        e += 0.5 *
             elasticEnergy(inter_[b], chordAt(ctx.particles, i, inter_[b]), par_.law, B.attr(b));
      return e;
    });
  }

  // The deformation of interaction k of particle i now, for outputs (the force loop uses
  // the cos and sin of the step instead).
  Chord chordAt(const Particles& P, std::size_t i, const Interaction& k) const {
    const double* a = P.alter(i);
    const double* aj = P.alter(k.j);
    const double rx = aj[AX] - a[AX], ry = aj[AY] - a[AY];
    if (par_.kinematics == "corotational")
      return corotChord(k, rx, ry, std::cos(a[THETA]), std::sin(a[THETA]), std::cos(aj[THETA]),
                        std::sin(aj[THETA]));
    return smallChord(k, rx - k.r0x, ry - k.r0y, a[THETA], aj[THETA]);
  }

  // ω_max of the undamaged lattice in small deformation (eq. 4.3), DOFs u_x, u_y, θ_z.
  double highestFrequency(Context& ctx) const {
    const Particles& P = ctx.particles;
    const std::size_t n = P.owned();
    DofSystem sys;
    sys.dofs = 3;
    sys.mass.resize(3 * n);
    sys.held.resize(3 * n);
    constexpr int bit[3] = {FIX_X, FIX_Y, FIX_T};
    for (std::size_t i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) {
        sys.mass[3 * i + d] = d < 2 ? in_.mass[i] : in_.inertia[i];
        sys.held[3 * i + d] = (in_.constraint[i] & bit[d]) != 0;
      }
    auto restoring = [&](std::span<const double> u, std::span<double> f) {
      for (std::size_t i = 0; i < n; ++i) {
        double fx = 0, fy = 0, m = 0;
        for (std::size_t b = ctx.bonds.begin(i); b < ctx.bonds.end(i); ++b) {
          const Interaction& k = inter_[b];
          const std::size_t j = static_cast<std::size_t>(k.j);
          const Chord ch = smallChord(k, u[3 * j] - u[3 * i], u[3 * j + 1] - u[3 * i + 1],
                                      u[3 * i + 2], u[3 * j + 2]);
          const EndLoad e = elasticForce(k, ch, DamageLaw{}, nullptr, false);
          fx += e.fx;
          fy += e.fy;
          m += e.m;
        }
        f[3 * i] = fx;
        f[3 * i + 1] = fy;
        f[3 * i + 2] = m;
      }
    };
    return pdq::highestFrequency(ctx, sys, restoring, par_.powerIterations);
  }

  std::string failureMode(Context& ctx) const {
    const Particles& P = ctx.particles;
    return mplm::failureMode(ctx, in_.constraint, [&](std::size_t i) { return &P.alter(i)[AX]; });
  }

  // cos θ and sin θ of every local particle (owned and ghosts), once per step.
  void turnings(const Particles& P) {
    const long nl = static_cast<long>(P.local());
    cs_.resize(2 * P.local());
#pragma omp parallel for schedule(static)
    for (long i = 0; i < nl; ++i) {
      const double th = P.alter(i)[THETA];
      if (std::fabs(th) <= 0.1) {
        // Particles turn little in most runs: Taylor series, exact to round-off here
        // (next terms below 1e-22 relative) and several times cheaper than sin and cos.
        // Coefficients 1/n! as constants: multiplications only.
        const double t2 = th * th;
        cs_[2 * i] =
            1 - t2 * (1.0 / 2 -
                      t2 * (1.0 / 24 -
                            t2 * (1.0 / 720 - t2 * (1.0 / 40320 - t2 * (1.0 / 3628800 -
                                                                        t2 * (1.0 / 479001600))))));
        cs_[2 * i + 1] =
            th * (1 - t2 * (1.0 / 6 -
                            t2 * (1.0 / 120 - t2 * (1.0 / 5040 -
                                                    t2 * (1.0 / 362880 - t2 * (1.0 / 39916800))))));
      } else {
        cs_[2 * i] = std::cos(th);
        cs_[2 * i + 1] = std::sin(th);
      }
    }
  }

  // Virial stress of particle i from its elastic interactions (no damping):
  // σ = (1/2ΔV) Σ_j r_ij ⊗ f_ij, symmetrised; ΔV the particle's volume.
  std::array<double, 3> stress(const Context& ctx, std::size_t i) const {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    const double* a = P.alter(i);
    double sxx = 0, syy = 0, sxy = 0;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const Interaction& k = inter_[b];
      const double* aj = P.alter(k.j);
      const double rx = aj[AX] - a[AX], ry = aj[AY] - a[AY];
      const Chord ch = chordAt(P, i, k);
      double state[N_BOND];
      std::copy_n(B.attr(b), N_BOND, state);
      const EndLoad e = elasticForce(k, ch, par_.law, state, false);
      sxx += rx * e.fx;
      syy += ry * e.fy;
      sxy += 0.5 * (rx * e.fy + ry * e.fx);
    }
    const double V = isSteel(P.fixed(i)) ? P.fixed(i)[AREA] * par_.s
                                         : std::sqrt(3.0) / 2 * par_.s * par_.s * par_.thickness;
    return {sxx / (2 * V), syy / (2 * V), sxy / (2 * V)};
  }

  Parameters2d par_;
  std::vector<Interaction> inter_;  // per bond, same index as ctx.bonds
  std::vector<double> cs_;          // cos θ, sin θ per local particle (co-rotational form)
  Inertia in_;
  double omegaMax_ = 0;
};

PDQ_REGISTER_MODEL(Mplm2d, "mplm2d",
                   "micropolar peridynamic lattice model, 2D: concrete with damage, steel bars");

}  // namespace
}  // namespace pdq::mplm
