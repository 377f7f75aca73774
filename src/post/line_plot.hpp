#pragma once
// Line plots (load-displacement curves, energy histories): several series on one pair
// of axes with ticks and numbers, axis labels, a title and a legend. PNG, SVG or PDF by
// the file's extension.
#include <array>
#include <string>
#include <vector>

#include "post/ticks.hpp"

namespace pdq::post {

struct Series {
  std::string name;          // the legend's entry
  std::vector<double> x, y;  // equal lengths; a non-finite value breaks the line
};

struct PlotStyle {
  std::string title, xLabel, yLabel;
  int width = 1000, height = 650;  // pixels (PNG) or points
  bool legend = true;
};

// Where data land on the picture: the plot area and its axes.
struct PlotFrame {
  int width = 0, height = 0;
  double left = 0, top = 0, right = 0, bottom = 0;  // plot area in pixels
  Ticks x, y;
  std::array<double, 2> pixel(double xv, double yv) const;
};

PlotFrame plotFrame(const std::vector<Series>& series, const PlotStyle& style);

// Draws the plot to `path`, written atomically. Throws InputError for series of unequal
// lengths or an unknown extension.
void plotLines(const std::vector<Series>& series, const PlotStyle& style, const std::string& path);

}  // namespace pdq::post
