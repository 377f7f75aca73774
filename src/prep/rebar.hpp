#pragma once
// Reinforcing bars as 1D lattices of steel particles (thesis §4.3.4): straight bars placed
// by diameter (or ASTM bar size) and centroid, 2D stirrups as vertical bars at a spacing,
// 3D stirrups as closed rectangular hoops at a spacing.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace pdq::prep {

using Point = std::array<double, 3>;

// A bar's section: its diameter and area (the nominal area of an ASTM size, else π d²/4).
struct BarSection {
  double diameter = 0;
  double nominalArea = 0;  // 0: π d²/4
  double area() const;
  double secondMoment() const;  // π d⁴/64
};

// The nominal diameter and area of an ASTM A615/A615M deformed bar by its soft-metric
// designation ("#10", "#13", "#16", "#19", "#22", "#25", "#29", "#32", "#36", "#43",
// "#57"); none for any other text. The sizes list is what an error message offers.
std::optional<BarSection> astmBar(const std::string& designation);
std::string astmBarSizes();

// A straight bar between the centroids of its end sections.
struct Bar {
  Point from{}, to{};
  BarSection section;
};

// Points along the bar, both ends included, evenly spaced at the largest spacing ≤ s.
std::vector<Point> barPoints(const Bar& bar, double s);

// A bar of the given diameter along X at height `centroid` above y = y0 (Z = 0), from
// x = xStart to x = xEnd.
Bar longitudinalBar(double xStart, double xEnd, double y0, double centroid, double diameter);

// Positions first, first + spacing, ... up to xMax: where stirrups stand.
std::vector<double> stations(double first, double spacing, double xMax);

// Vertical stirrups at the stations from y = yBottom to yTop (Z = 0), one bar each.
std::vector<Bar> stirrups(double first, double spacing, double xMax, double yBottom, double yTop,
                          double diameter);

// A closed rectangular hoop in the plane X = x, its centre line the rectangle
// [yLo, yHi] × [zLo, zHi].
struct Hoop {
  double x = 0, yLo = 0, yHi = 0, zLo = 0, zHi = 0;
  BarSection section;
};
// Points around the hoop's centre line, each once: the corners and each side divided
// evenly at the largest spacing ≤ s, in order around the loop.
std::vector<Point> hoopPoints(const Hoop& hoop, double s);

}  // namespace pdq::prep
