// The linear peridynamic solid (LPS) of Silling et al. (2007), ordinary state-based. Per
// particle i, with ω the influence function, e = |Y| - |ξ| the bond extension and
// m_i = Σ_j ω |ξ|² V_j the weighted volume:
//   dilatation     θ_i = (D / m_i) Σ_j ω |ξ| e V_j                (D = 2 or 3)
//   force state    t_ij = ω [ A θ_i |ξ| / m_i + B e / m_i ]
//   acceleration   ρ a_i = Σ_j (t_ij + t_ji) V_j along the bond
// 3D: A = 3K - 5μ, B = 15μ. 2D plane stress (thickness t in the volumes): A = 2κ - 4μ,
// B = 8μ with κ = E / (2 (1 - ν)), the in-plane bulk modulus. A force step has two passes:
// the dilatation of every owned particle, a refresh of the ghosts' dilatation, then the
// forces. Per bond the model keeps |ξ|, ω V_j w (0 once broken) and the partner's 1/m.
#include <cmath>

#include "engine/error.hpp"
#include "models/lps/lps_kernel.hpp"
#include "models/peri/bond_classes.hpp"
#include "models/peri/peri_model.hpp"

namespace pdq::peri {
namespace {

class Lps final : public PeriModel {
  enum { INV_M = WEIGHT + 1 };

  void configureModel(const Params& p) override {
    nu_ = p.number("nu");
    if (!(nu_ > -1 && nu_ < 0.5)) {
      const auto r = p.raw("nu");
      throw InputError(r ? r->file : p.owner(), r ? r->line : 0, "nu must lie in (-1, 0.5)");
    }
    constantInfluence_ = p.choice("influence", "inverse", {"inverse", "constant"}) == "constant";
  }
  std::vector<std::string> bondExtra() const override { return {"inv_m"}; }

  void prepareBonds(Context& ctx, const std::vector<double>& volume) override {
    Particles& P = ctx.particles;
    Bonds& B = ctx.bonds;
    const double mu = E_ / (2 * (1 + nu_));
    if (dim_ == 3) {
      kappa_ = E_ / (3 * (1 - 2 * nu_));
      A_ = 3 * kappa_ - 5 * mu;
      B_ = 15 * mu;
    } else {
      kappa_ = E_ / (2 * (1 - nu_));
      A_ = 2 * kappa_ - 4 * mu;
      B_ = 8 * mu;
    }
    invM_.assign(P.owned(), 0.0);
    for (std::size_t i = 0; i < P.owned(); ++i) {
      double m = 0;
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        double* a = B.attr(b);
        a[WEIGHT] = (constantInfluence_ ? 1.0 : 1.0 / a[XI]) * volume[b];
        m += a[WEIGHT] * a[XI] * a[XI];
      }
      invM_[i] = m > 0 ? 1.0 / m : 0.0;
    }
    const std::vector<double> invM = onGhosts(ctx, invM_);
    for (std::size_t i = 0; i < P.owned(); ++i)
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) B.attr(b)[INV_M] = invM[B.partner(b)];
    // Made here, with the bonds: its first touch of memory is not a time step's.
    classes_.forget();
    if (kernels_.readRows) keepRows(P, B);
  }

  // The vector kernels' bond rows, rebuilt with each partner's 1/m (for the packed rows'
  // fourth column, as its bonds hold it) when the bonds have changed.
  BondRows keepRows(const Particles& P, const Bonds& B) {
    if (classes_.update(B)) {
      partnerInvM_.assign(P.local(), 0.0);
      for (std::size_t b = 0; b < B.count(); ++b)
        if (B.partner(b) >= 0) partnerInvM_[B.partner(b)] = B.attr(b)[INV_M];
    }
    return classes_.rows();
  }

  void force(Context& ctx) override {
    Particles& P = ctx.particles;
    Bonds& B = ctx.bonds;
    const long n = static_cast<long>(P.owned());
    if (B.empty()) {
      for (long i = 0; i < n; ++i) std::fill_n(P.integ(i), 3, 0.0);
      return;
    }
    theta_.resize(P.local());
    const LpsKernels k = kernels_;
    const BondRows rows = k.readRows ? keepRows(P, B) : BondRows{};
    const double* x = packed_.pack(P, k.readRows ? partnerInvM_.data() : nullptr);
    const LpsView view{B.partners().data(),
                       B.attr(0),
                       rows,
                       x,
                       PackedPositions::kRow,
                       theta_.data(),
                       A_ / density_,
                       B_ / density_,
                       criticalStretch_,
                       &B};
    const double D = dim_;
    // Pass 1: dilatation of the owned particles, then to the ghosts.
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i)
      theta_[i] = D * invM_[i] * k.dilatation(view, i, B.begin(i), B.end(i));
    ctx.refreshGhosts(theta_, 1);
    // Pass 2: forces.
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i)
      k.force(view, i, B.begin(i), B.end(i), theta_[i] * invM_[i], invM_[i], P.integ(i));
  }

  // V_i W_i, W_i = κ θ² / 2 + (B / 2 m_i) Σ_j ω (e - θ |ξ| / D)² V_j, with θ recomputed
  // from the current positions.
  double particleEnergy(const Context& ctx, std::size_t i) const override {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    const double D = dim_;
    const double* xi = P.alter(i);
    std::vector<double> ext(B.end(i) - B.begin(i));
    double th = 0;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const double* xj = P.alter(B.partner(b));
      const double* a = B.attr(b);
      ext[b - B.begin(i)] = std::hypot(xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]) - a[XI];
      th += a[WEIGHT] * a[XI] * ext[b - B.begin(i)];
    }
    th *= D * invM_[i];
    double dev = 0;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const double* a = B.attr(b);
      const double ed = ext[b - B.begin(i)] - th * a[XI] / D;
      dev += a[WEIGHT] * ed * ed;
    }
    return P.fixed(i)[VOLUME] * (0.5 * kappa_ * th * th + 0.5 * B_ * invM_[i] * dev);
  }

  bool constantInfluence_ = false;
  LpsKernels kernels_ = lpsKernels();
  double kappa_ = 0, A_ = 0, B_ = 0;
  std::vector<double> invM_;         // 1 / m of the owned particles (they never move between ranks)
  std::vector<double> theta_;        // dilatation of every local particle, within a force step
  BondClasses classes_;              // the vector kernels' bond rows
  std::vector<double> partnerInvM_;  // 1/m of every local particle that is a partner
};

PDQ_REGISTER_MODEL(Lps, "lps", "linear peridynamic solid (ordinary state-based peridynamics)");

}  // namespace
}  // namespace pdq::peri
