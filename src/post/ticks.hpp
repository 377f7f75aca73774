#pragma once
// Axis ticks at "nice" numbers (1, 2 or 5 times a power of ten) and their labels.
#include <string>
#include <vector>

namespace pdq::post {

struct Ticks {
  double lo, hi;  // the axis range, widened to whole ticks
  double step;
  std::vector<double> values;
};

// About `target` ticks covering [lo, hi]; a zero-width range is widened around its value.
Ticks niceTicks(double lo, double hi, int target = 6);
// A tick's label with just enough digits for the tick step (scientific for very large
// or small magnitudes).
std::string tickLabel(double value, double step);

}  // namespace pdq::post
