#pragma once
// Colours of pdq's pictures: the damage ramp of the thesis's Fig. 4.5 (yellow for little
// damage, through orange and red, to black for a broken interaction), a perceptually
// uniform ramp for any other quantity, and distinct colours for plot series.
#include <cstddef>

namespace pdq::post {

struct Rgb {
  double r = 0, g = 0, b = 0;
};

// Damage ω in [0, 1] (clamped): 0 yellow, 1/3 orange, 2/3 red, 1 black.
Rgb damageColour(double omega);
// t in [0, 1] (clamped), dark blue-violet through teal and green to yellow (viridis).
Rgb valueColour(double t);
// The k-th series colour (cycles after ten).
Rgb seriesColour(std::size_t k);

}  // namespace pdq::post
