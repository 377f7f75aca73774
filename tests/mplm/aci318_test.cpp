// ACI 318 strengths of the thesis's 2D beams against hand calculations (written out in the
// comments) and against the values the thesis quotes.
#include "studies/aci318.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pdq::mplm::aci318 {
namespace {

double barArea(double d) { return std::numbers::pi * d * d / 4; }

// §4.4.3–4.4.6 section: b = 0.12 m, h = 0.26 m, bar centroid 0.02 m up: d = 0.24 m.
Section thesisBeam(double bar, double stirrup) {
  Section s;
  s.b = 0.12;
  s.h = 0.26;
  s.d = 0.24;
  s.As = barArea(bar);
  if (stirrup > 0) {
    s.Av = barArea(stirrup);  // one vertical bar per position in the 2D model
    s.sv = 0.15;
  }
  return s;
}

TEST(Aci318, PlainBeamCrackingLoad) {
  // M_cr = f_t b h²/6 = 2.758e6 · 0.12 · 0.26² / 6 = 3728.8 N·m; w = 8 M / L² = 22.17 kN/m.
  const double w = uniformLoadFromMoment(crackingMoment(2.758e6, 0.12, 0.26), 1.16);
  EXPECT_NEAR(w, 22169, 5);
  EXPECT_NEAR(w, 22140, 0.005 * 22140);  // thesis: 22.14 kN/m
}

TEST(Aci318, SinglyReinforcedBeamFlexure) {
  // A_s = π 0.0127²/4 = 1.26677e-4 m²; T = A_s f_y = 52444 N;
  // a = T / (0.85 f'c b) = 52444 / 2.81316e6 = 0.018642 m (c = a/0.85 = 0.02193 m,
  // ε_s = 0.003 (d − c)/c = 0.0298: yields); M_n = T (d − a/2) = 12098 N·m;
  // w = 8 M_n / 1.16² = 71.93 kN/m.
  const Section s = thesisBeam(0.0127, 0);
  EXPECT_NEAR(beta1(s.fc), 0.85, 1e-12);
  EXPECT_NEAR(beta1(s.fc) * neutralAxis(s), 0.018642, 1e-6);
  EXPECT_NEAR(flexuralStrength(s), 12098, 1);
  const Capacity c = simplySupportedUniform(s, 1.16);
  EXPECT_NEAR(c.flexure, 71930, 10);
  EXPECT_NEAR(c.flexure, 72240, 0.005 * 72240);  // thesis: 72.24 kN/m
}

TEST(Aci318, ShearCriticalBeam) {
  // 3.175 cm bar: A_s = 7.917e-4 m², T = 327.8 kN, a = 0.11651 m, M_n = 59.57 kN·m,
  // w_flexure = 354.2 kN/m. Shear: V_c = 0.17 √27.58 · 0.12 · 0.24 MN = 25.71 kN;
  // V_s = A_v f_y d / s = 7.854e-5 · 414e6 · 0.24 / 0.15 = 52.03 kN; V_n = 77.74 kN;
  // at d from the support w = V_n / (0.58 − 0.24) = 228.6 kN/m (2 V_n / L = 134.0 kN/m).
  const Section s = thesisBeam(0.03175, 0.01);
  EXPECT_NEAR(flexuralStrength(s), 59570, 10);
  EXPECT_NEAR(concreteShear(s), 25713, 2);
  EXPECT_NEAR(steelShear(s), 52026, 2);
  const Capacity c = simplySupportedUniform(s, 1.16);
  EXPECT_NEAR(c.flexure, 354150, 100);
  EXPECT_NEAR(c.shear, 228640, 50);
  EXPECT_EQ(c.mode(), "shear");  // as the thesis says (it quotes 210 kN/m)
  EXPECT_NEAR(simplySupportedUniform(s, 1.16, false).shear, 134040, 50);
}

TEST(Aci318, StirrupsDoNotChangeFlexuralFailure) {
  const Capacity c = simplySupportedUniform(thesisBeam(0.0127, 0.01), 1.16);
  EXPECT_EQ(c.mode(), "flexural");  // §4.4.5: bending failure, 72.24 kN/m
  EXPECT_NEAR(c.governing(), 71930, 10);
}

TEST(Aci318, LargeBeamShear) {
  // 4.06 × 1.02 × 0.41 m, 10.16 cm bar at 5.1 cm (d = 0.969 m), 2.54 cm stirrups at 43.2 cm:
  // V_c = 0.17 √27.58 · 0.41 · 0.969 MN = 354.7 kN; V_s = 5.067e-4 · 414e6 · 0.969/0.432
  // = 470.6 kN; V_n = 825.3 kN; w = V_n / (2.03 − 0.969) = 777.9 kN/m. Flexure: a = 0.3492 m,
  // M_n = 2666 kN·m, w = 1294 kN/m, so shear governs (the thesis quotes 599 kN/m).
  Section s;
  s.b = 0.41;
  s.h = 1.02;
  s.d = 1.02 - 0.051;
  s.As = barArea(0.1016);
  s.Av = barArea(0.0254);
  s.sv = 0.432;
  const Capacity c = simplySupportedUniform(s, 4.06);
  EXPECT_NEAR(concreteShear(s), 354690, 100);
  EXPECT_NEAR(steelShear(s), 470640, 100);
  EXPECT_NEAR(c.shear, 777900, 300);
  EXPECT_NEAR(c.flexure, 1294000, 2000);
  EXPECT_EQ(c.mode(), "shear");
}

TEST(Aci318, OverReinforcedSteelDoesNotYield) {
  // A_s = 0.01 m² in the 0.12 × 0.26 section: the steel stays elastic (f_s < f_y) and
  // the compression block balances E_s ε_s A_s.
  Section s = thesisBeam(0.0127, 0);
  s.As = 0.01;
  const double c = neutralAxis(s);
  const double fs = s.Es * 0.003 * (s.d - c) / c;
  EXPECT_LT(fs, s.fy);
  EXPECT_NEAR(0.85 * s.fc * s.b * 0.85 * c, s.As * fs, 1e-6 * s.As * fs);
}

}  // namespace
}  // namespace pdq::mplm::aci318
