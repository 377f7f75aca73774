#include "prep/rebar.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/memory.hpp"

namespace pdq::prep {
namespace {

// ASTM A615/A615M, Table 1 (deformed bar designation numbers, nominal weights, nominal
// dimensions): soft-metric size, nominal diameter (mm), nominal cross-sectional area (mm²).
struct AstmSize {
  const char* name;
  double diameterMm, areaMm2;
};
constexpr AstmSize astmSizes[] = {{"#10", 9.5, 71},    {"#13", 12.7, 129}, {"#16", 15.9, 199},
                                  {"#19", 19.1, 284},  {"#22", 22.2, 387}, {"#25", 25.4, 510},
                                  {"#29", 28.7, 645},  {"#32", 32.3, 819}, {"#36", 35.8, 1006},
                                  {"#43", 43.0, 1452}, {"#57", 57.3, 2581}};

// n + 1 points from a to b, evenly spaced, both ends included.
void appendSegment(std::vector<Point>& out, const Point& a, const Point& b, long n, bool last) {
  for (long k = 0; k < n + (last ? 1 : 0); ++k) {
    const double f = static_cast<double>(k) / static_cast<double>(n);
    out.push_back({a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])});
  }
}

// Segments of the largest spacing ≤ s along a length (at least one).
long segments(double length, double s) {
  return std::max(1L, static_cast<long>(std::ceil(length / s - 1e-9)));
}

}  // namespace

double BarSection::area() const {
  return nominalArea > 0 ? nominalArea : std::numbers::pi * diameter * diameter / 4;
}
double BarSection::secondMoment() const { return std::numbers::pi * std::pow(diameter, 4) / 64; }

std::optional<BarSection> astmBar(const std::string& designation) {
  for (const AstmSize& a : astmSizes)
    if (designation == a.name) return BarSection{a.diameterMm * 1e-3, a.areaMm2 * 1e-6};
  return std::nullopt;
}

std::string astmBarSizes() {
  std::string out;
  for (const AstmSize& a : astmSizes) out += (out.empty() ? "" : ", ") + std::string(a.name);
  return out;
}

std::vector<Point> barPoints(const Bar& bar, double s) {
  if (!(s > 0) || !(bar.section.diameter > 0))
    throw std::invalid_argument("a bar needs a positive diameter and spacing");
  const double len =
      std::hypot(bar.to[0] - bar.from[0], bar.to[1] - bar.from[1], bar.to[2] - bar.from[2]);
  checkParticleCount(len / s + 1, sizeof(Point), "a bar");
  std::vector<Point> pts;
  appendSegment(pts, bar.from, bar.to, segments(len, s), true);
  return pts;
}

Bar longitudinalBar(double xStart, double xEnd, double y0, double centroid, double diameter) {
  return {{xStart, y0 + centroid, 0}, {xEnd, y0 + centroid, 0}, {diameter}};
}

std::vector<double> stations(double first, double spacing, double xMax) {
  if (!(spacing > 0)) throw std::invalid_argument("stirrup spacing must be positive");
  checkParticleCount((xMax - first) / spacing + 1, sizeof(double), "the stirrups");
  std::vector<double> x;
  for (long k = 0; first + k * spacing <= xMax + 1e-9 * spacing; ++k)
    x.push_back(first + k * spacing);
  return x;
}

std::vector<Bar> stirrups(double first, double spacing, double xMax, double yBottom, double yTop,
                          double diameter) {
  std::vector<Bar> bars;
  for (double x : stations(first, spacing, xMax))
    bars.push_back({{x, yBottom, 0}, {x, yTop, 0}, {diameter}});
  return bars;
}

std::vector<Point> hoopPoints(const Hoop& h, double s) {
  if (!(s > 0) || !(h.section.diameter > 0) || !(h.yHi > h.yLo) || !(h.zHi > h.zLo))
    throw std::invalid_argument("a hoop needs a positive diameter, spacing and size");
  const Point corner[4] = {
      {h.x, h.yLo, h.zLo}, {h.x, h.yHi, h.zLo}, {h.x, h.yHi, h.zHi}, {h.x, h.yLo, h.zHi}};
  std::vector<Point> pts;
  for (int c = 0; c < 4; ++c) {
    const Point &a = corner[c], &b = corner[(c + 1) % 4];
    const double len = std::fabs(b[1] - a[1]) + std::fabs(b[2] - a[2]);  // along Y or Z
    appendSegment(pts, a, b, segments(len, s), false);
  }
  return pts;
}

}  // namespace pdq::prep
