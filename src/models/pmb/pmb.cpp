// Silling's prototype microelastic brittle (PMB) bond-based peridynamic model. Each bond
// pulls with force c s V_i V_j along it (s = stretch, c the micromodulus), and breaks for
// good once its stretch exceeds the critical stretch. The bond constant kept per bond is
// the partner's share of the acceleration per unit extension, c V_j w g / (ρ |ξ|) (w the
// partial-volume weight, g the optional surface correction), so the kernel (pmb_kernel.hpp)
// does one square root, one division and a few multiply-adds per bond.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "models/peri/peri_model.hpp"
#include "models/pmb/pmb_kernel.hpp"

namespace pdq::peri {
namespace {

class Pmb final : public PeriModel {
  void configureModel(const Params& p) override {
    surfaceCorrection_ = p.flag("surface_correction", false);
  }

  // Surface correction (the energy method): under a uniaxial strain ε along axis a, the
  // continuum stores c ε² Q_a / 4 per unit volume, Q_a = ∫ |ξ| n_a⁴ dV over a full horizon
  // (π t δ³ / 4 in 2D, π δ⁴ / 5 in 3D), and particle i stores c ε² q_a / 4 with the
  // discrete sum q_a = Σ_j V_j w |ξ| n_a⁴. Its factors g_a = Q_a / q_a restore the
  // continuum stiffness along every axis, in the bulk (the lattice sum) and near
  // surfaces alike; a bond takes the mean of its ends' factors per axis and combines
  // them along its direction n as G = (Σ_a n_a² / g_a²)^(-1/2).
  void prepareBonds(Context& ctx, const std::vector<double>& volume) override {
    Particles& P = ctx.particles;
    Bonds& B = ctx.bonds;
    c_ = pmbMicromodulus(dim_, E_, delta_, thickness_);
    const std::size_t D = static_cast<std::size_t>(dim_);
    std::vector<double> g;  // g_a of every local particle, D per particle
    if (surfaceCorrection_) {
      const double pi = std::numbers::pi;
      const double full =
          dim_ == 3 ? pi * std::pow(delta_, 4) / 5 : pi * thickness_ * std::pow(delta_, 3) / 4;
      std::vector<double> own(D * P.owned());
      for (std::size_t i = 0; i < P.owned(); ++i) {
        const double* Xi = P.fixed(i);
        for (std::size_t a = 0; a < D; ++a) {
          double q = 0;
          for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
            const double r = B.attr(b)[XI], n = (P.fixed(B.partner(b))[a] - Xi[a]) / r;
            q += volume[b] * r * n * n * n * n;
          }
          own[D * i + a] = q > 0 ? full / q : 1.0;
        }
      }
      g = onGhosts(ctx, own, dim_);
    }
    for (std::size_t i = 0; i < P.owned(); ++i)
      for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
        double* attr = B.attr(b);
        const std::size_t j = B.partner(b);
        double factor = 1;
        if (surfaceCorrection_) {
          double sum = 0;
          for (std::size_t a = 0; a < D; ++a) {
            const double n = (P.fixed(j)[a] - P.fixed(i)[a]) / attr[XI];
            const double ga = 0.5 * (g[D * i + a] + g[D * j + a]);
            sum += n * n / (ga * ga);
          }
          factor = 1 / std::sqrt(sum);
        }
        attr[WEIGHT] = c_ * volume[b] * factor / (density_ * attr[XI]);
      }
    // Made here, with the bonds: its first touch of memory is not a time step's.
    classes_.forget();
    if (kernel_.readRows) classes_.update(B);
  }

  void force(Context& ctx) override {
    Particles& P = ctx.particles;
    Bonds& B = ctx.bonds;
    if (B.empty()) {
      for (std::size_t i = 0; i < P.owned(); ++i) std::fill_n(P.integ(i), 3, 0.0);
      return;
    }
    const PmbKernel kernel = kernel_;
    if (kernel.readRows) classes_.update(B);
    const PmbView view{B.partners().data(),
                       B.attr(0),
                       kernel.readRows ? classes_.rows() : BondRows{},
                       packed_.pack(P),
                       PackedPositions::kRow,
                       criticalStretch_,
                       &B};
    // Two particles a call: the AVX-512 kernel takes them together.
    const long n = static_cast<long>(P.owned()), stride = P.schema().nInteg();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; i += 2) kernel.force(view, i, std::min(i + 2, n), P.integ(0), stride);
  }

  // Half the energy of its bonds, ½ c s² |ξ| V_i V_j w g each.
  double particleEnergy(const Context& ctx, std::size_t i) const override {
    const Particles& P = ctx.particles;
    const Bonds& B = ctx.bonds;
    const double* xi = P.alter(i);
    double e = 0;
    for (std::size_t b = B.begin(i); b < B.end(i); ++b) {
      const double* xj = P.alter(B.partner(b));
      const double* a = B.attr(b);
      const double len = std::hypot(xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]);
      e += a[WEIGHT] * (len - a[XI]) * (len - a[XI]);
    }
    return 0.25 * density_ * P.fixed(i)[VOLUME] * e;
  }

  bool surfaceCorrection_ = false;
  PmbKernel kernel_ = pmbKernel();
  BondClasses classes_{PackedPositions::kRow};  // the vector kernels' bond rows
  double c_ = 0;
};

PDQ_REGISTER_MODEL(Pmb, "pmb", "bond-based prototype microelastic brittle peridynamics");

}  // namespace
}  // namespace pdq::peri
