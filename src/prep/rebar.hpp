#pragma once
// Reinforcing bars as 1D lattices of steel particles (thesis §4.3.4): straight bars placed
// by diameter and centroid, stirrups as vertical bars at a spacing.
#include <array>
#include <vector>

namespace pdq::prep {

struct Bar {
  double x0, y0, x1, y1;  // end points of the centroid line
  double diameter;
  double area() const;          // π d²/4
  double secondMoment() const;  // π d⁴/64
};

// Points along the bar, both ends included, evenly spaced at the largest spacing ≤ s.
std::vector<std::array<double, 2>> barPoints(const Bar& bar, double s);

// A horizontal bar of the given diameter with its centroid `centroid` above y = y0,
// running from x = xStart to x = xEnd.
Bar longitudinalBar(double xStart, double xEnd, double y0, double centroid, double diameter);

// Vertical stirrups at x = first, first + spacing, ... up to xMax, from y = yBottom to yTop.
std::vector<Bar> stirrups(double first, double spacing, double xMax, double yBottom, double yTop,
                          double diameter);

}  // namespace pdq::prep
