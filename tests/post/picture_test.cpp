// The renderer: small known pictures, checked pixel by pixel.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "engine/error.hpp"
#include "png_pixels.hpp"
#include "post/colour.hpp"
#include "post/lattice_picture.hpp"
#include "post/line_plot.hpp"

namespace pdq {
namespace {

using post::Rgb;
const Rgb kWhite{1, 1, 1}, kBlack{0, 0, 0}, kGrey{0.55, 0.55, 0.55};

// Two rows of three particles at unit spacing.
post::LatticeImage twoRows() {
  post::LatticeImage im;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) im.position.insert(im.position.end(), {double(i), double(j), 0});
  im.bonds = {{0, 1}, {1, 2}, {3, 4}, {4, 5}};
  im.bondDamage = {1.0, 0.0, 0.5, 0.1};
  return im;
}

std::array<double, 2> mid(const post::LatticeFrame& f, const post::LatticeImage& im, int a, int b) {
  const auto pa = f.pixel(&im.position[3 * a]), pb = f.pixel(&im.position[3 * b]);
  return {0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1])};
}

TEST(Picture, DamagedBondsColouredUndamagedHidden) {
  const auto im = twoRows();
  post::PictureStyle st;
  st.width = 600;
  st.title = "damage";
  post::renderLattice(im, st, "bonds.png");
  const auto f = post::latticeFrame(im, st);
  test::Png png("bonds.png");
  ASSERT_EQ(png.width(), 600);
  ASSERT_EQ(png.height(), f.height);
  auto at = [&](std::array<double, 2> p) { return png.at(p[0], p[1]); };
  EXPECT_LT(test::distance(at(mid(f, im, 0, 1)), kBlack), 0.02);  // broken: black
  EXPECT_LT(test::distance(at(mid(f, im, 1, 2)), kWhite), 0.02);  // intact: not drawn
  EXPECT_LT(test::distance(at(mid(f, im, 3, 4)), post::damageColour(0.5)), 0.02);
  EXPECT_LT(test::distance(at(mid(f, im, 4, 5)), post::damageColour(0.1)), 0.02);
  // The ramp runs yellow -> red -> black.
  EXPECT_GT(post::damageColour(0.1).g, 0.7);
  EXPECT_LT(post::damageColour(0.7).g, 0.1);
  EXPECT_GT(post::damageColour(0.7).r, 0.7);
  // Particle 2 (only intact bonds) is a grey dot; far from everything is white.
  EXPECT_LT(test::distance(at(f.pixel(&im.position[6])), kGrey), 0.02);
  const double below[3] = {1, -0.5, 0};
  EXPECT_LT(test::distance(at(f.pixel(below)), kWhite), 0.02);
}

TEST(Picture, DisplacementMagnified) {
  post::LatticeImage im;
  im.position = {0, 0, 0, 4, 0, 0, 0, 2, 0, 4, 2, 0};
  im.displacement = {0, 0, 0, 0.01, 0, 0, 0, 0, 0, 0, 0, 0};
  post::PictureStyle st;
  st.width = 500;
  st.magnification = 100;  // particle 1 drawn at x = 5
  st.dotRadius = 6;
  post::renderLattice(im, st, "magnified.png");
  const auto f = post::latticeFrame(im, st);
  test::Png png("magnified.png");
  const double moved[3] = {5, 0, 0}, original[3] = {4, 0, 0};
  EXPECT_LT(test::distance(png.at(f.pixel(moved)[0], f.pixel(moved)[1]), kGrey), 0.02);
  EXPECT_LT(test::distance(png.at(f.pixel(original)[0], f.pixel(original)[1]), kWhite), 0.02);
}

TEST(Picture, ValuesColourDotsNearerOnTop) {
  // Viewed along X: particles at the same (y, z) overlap; the nearer one (larger x) shows.
  post::LatticeImage im;
  im.position = {0, 0, 0, 1, 0, 0, 0, 3, 0, 0, 0, 2, 0, 3, 2};
  im.values = {0, 1, 0.5, 0.5, 0.5};
  im.valueName = "value";
  post::PictureStyle st;
  st.width = 500;
  st.view = post::parseView("x");
  post::renderLattice(im, st, "values.png");
  const auto f = post::latticeFrame(im, st);
  // Screen right is world Y, screen up world Z.
  EXPECT_NEAR(f.right[1], 1, 1e-12);
  EXPECT_NEAR(f.up[2], 1, 1e-12);
  test::Png png("values.png");
  const auto p = f.pixel(&im.position[0]);
  EXPECT_LT(test::distance(png.at(p[0], p[1]), post::valueColour(1)), 0.02);
  const auto q = f.pixel(&im.position[6]);
  EXPECT_LT(test::distance(png.at(q[0], q[1]), post::valueColour(0.5)), 0.02);
  // Above the lowest point (z = 0) and the highest (z = 2) along screen Y.
  EXPECT_GT(f.pixel(&im.position[0])[1], f.pixel(&im.position[9])[1]);
  EXPECT_THROW(post::parseView("sideways"), InputError);
}

std::string head(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  return s;
}

TEST(Picture, VectorFormatsByExtension) {
  const auto im = twoRows();
  post::PictureStyle st;
  st.width = 400;
  post::renderLattice(im, st, "bonds.svg");
  post::renderLattice(im, st, "bonds.pdf");
  EXPECT_NE(head("bonds.svg", 200).find("<svg"), std::string::npos);
  EXPECT_EQ(head("bonds.pdf", 5), "%PDF-");
  EXPECT_THROW(post::renderLattice(im, st, "bonds.jpg"), InputError);
  auto bad = im;
  bad.bondDamage.pop_back();
  EXPECT_THROW(post::renderLattice(bad, st, "bad.png"), InputError);
}

TEST(Plot, SeriesDrawnInTheirColours) {
  post::Series load{"load", {0, 1, 2, 3, 4}, {0, 10, 20, 30, 40}};
  post::Series flat{"flat", {0, 4}, {35, 35}};
  post::PlotStyle st;
  st.title = "load-displacement";
  st.xLabel = "displacement (mm)";
  st.yLabel = "load (kN)";
  post::plotLines({load, flat}, st, "plot.png");
  const auto f = post::plotFrame({load, flat}, st);
  test::Png png("plot.png");
  ASSERT_EQ(png.width(), st.width);
  // On each line between data points: the series' colour.
  const auto a = f.pixel(2.5, 25), b = f.pixel(3, 35);
  EXPECT_LT(test::distance(png.at(a[0], a[1]), post::seriesColour(0)), 0.05);
  EXPECT_LT(test::distance(png.at(b[0], b[1]), post::seriesColour(1)), 0.05);
  // Below the line, between grid lines: white.
  const auto c = f.pixel(3.3, 13);
  EXPECT_LT(test::distance(png.at(c[0], c[1]), kWhite), 0.02);
  // Ticks cover the data with nice steps.
  EXPECT_LE(f.x.lo, 0);
  EXPECT_GE(f.x.hi, 4);
  EXPECT_LE(f.y.lo, 0);
  EXPECT_GE(f.y.hi, 40);
  EXPECT_EQ(post::tickLabel(0.5, 0.1), "0.5");
  EXPECT_EQ(post::tickLabel(20000, 5000), "20000");
  EXPECT_THROW(post::plotLines({{"bad", {1, 2}, {1}}}, st, "bad.png"), InputError);
}

}  // namespace
}  // namespace pdq
