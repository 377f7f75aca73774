#include "studies/aci318.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pdq::aci318 {
namespace {

double sqrtFcMPa(double fc) { return std::sqrt(fc / 1e6) * 1e6; }  // √f'c in MPa, as Pa

void check(const Section& s) {
  if (!(s.b > 0 && s.d > 0 && s.h >= s.d && s.fc > 0 && s.fy > 0 && s.Es > 0))
    throw std::invalid_argument(
        "ACI 318 section needs b > 0, 0 < d <= h, f'c > 0, f_y > 0, E_s > 0");
  if (s.Av > 0 && !(s.fyt > 0)) throw std::invalid_argument("ACI 318 stirrups need f_yt > 0");
}

}  // namespace

double beta1(double fc) {
  const double mpa = fc / 1e6;
  if (mpa <= 28) return 0.85;
  return std::max(0.65, 0.85 - 0.05 * (mpa - 28) / 7);
}

double neutralAxis(const Section& s) {
  check(s);
  if (!(s.As > 0)) return 0;
  const double k = 0.85 * s.fc * s.b * beta1(s.fc);
  // Compression k c minus tension A_s f_s(c) grows with c: bisection on (0, d].
  auto excess = [&](double c) {
    const double fs = std::min(s.fy, s.Es * 0.003 * (s.d - c) / c);
    return k * c - s.As * fs;
  };
  double lo = 0, hi = s.d;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * s.d; ++it) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

double flexuralStrength(const Section& s) {
  const double c = neutralAxis(s);
  if (c == 0) return 0;
  const double fs = std::min(s.fy, s.Es * 0.003 * (s.d - c) / c);
  const double a = beta1(s.fc) * c;
  return s.As * fs * (s.d - a / 2);
}

double crackingMoment(double ft, double b, double h) { return ft * b * h * h / 6; }

double concreteShear(const Section& s) {
  check(s);
  return 0.17 * s.lambda * sqrtFcMPa(s.fc) * s.b * s.d;
}

double steelShear(const Section& s) {
  check(s);
  if (!(s.Av > 0 && s.sv > 0)) return 0;
  return std::min(s.Av * s.fyt * s.d / s.sv, 0.66 * sqrtFcMPa(s.fc) * s.b * s.d);
}

double shearStrength(const Section& s) { return concreteShear(s) + steelShear(s); }

double uniformLoadFromMoment(double M, double span) { return 8 * M / (span * span); }

double uniformLoadFromShear(double V, double span, double d, bool atCriticalSection) {
  if (!atCriticalSection) return 2 * V / span;
  if (!(span / 2 > d)) throw std::invalid_argument("span too short for a critical section at d");
  return V / (span / 2 - d);
}

Capacity simplySupportedUniform(const Section& s, double span, bool atCriticalSection) {
  return {uniformLoadFromMoment(flexuralStrength(s), span),
          uniformLoadFromShear(shearStrength(s), span, s.d, atCriticalSection)};
}

Capacity cantileverTip(const Section& s, double length) {
  return {flexuralStrength(s) / length, shearStrength(s)};
}

}  // namespace pdq::aci318
