#pragma once
// Pictures of a lattice: the particles at their deformed positions (displacement
// magnified) as dots, the damaged bonds as lines coloured by damage as in the thesis's
// Fig. 4.5 (undamaged bonds hidden, yellow for little damage through orange and red to
// black for broken, with a legend), and optionally the particles coloured by any
// per-particle value with a colour bar. 2D, or any 3D lattice projected along a chosen
// view direction. PNG, SVG or PDF by the file's extension.
//
// The input is plain arrays, so the same function draws a running simulation's
// gathered state (PictureOutput), or data read back from restart or output files.
#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace pdq::post {

struct LatticeImage {
  std::vector<double> position;                   // reference positions, x y z per particle
  std::vector<double> displacement;               // x y z per particle; empty: undeformed
  std::vector<std::array<std::size_t, 2>> bonds;  // particle indices of each bond's ends
  std::vector<double> bondDamage;                 // per bond, 0 (intact) .. 1 (broken)
  std::vector<double> values;  // per particle, to colour the dots by; empty: grey dots
  std::string valueName;       // the colour bar's label

  std::size_t particles() const { return position.size() / 3; }
};

struct PictureStyle {
  double magnification = 1;               // displacements are drawn this many times larger
  std::array<double, 3> view{0, 0, 1};    // direction from the lattice towards the viewer
  int width = 1600;                       // pixels (PNG) or points (SVG, PDF)
  int height = 0;                         // 0: from the lattice's aspect ratio
  double dotRadius = 0;                   // pixels; 0: a fifth of the typical spacing
  double damageThreshold = 0;             // bonds with damage at or below it are hidden
  double valueMin = NAN, valueMax = NAN;  // colour bar range; NaN: the values' range
  std::string title;
};

// Where world points land on the picture (orthographic projection along `view`).
struct LatticeFrame {
  int width = 0, height = 0;
  std::array<double, 3> right{}, up{}, toViewer{};
  double scale = 1;       // pixels per length unit
  double x0 = 0, y0 = 0;  // pixel of the world origin's projection
  double dotRadius = 1;   // pixels
  std::array<double, 2> pixel(const double* p) const;
  double depth(const double* p) const;  // larger is nearer the viewer
};

// The frame renderLattice uses for this image and style (for tests and annotations).
LatticeFrame latticeFrame(const LatticeImage& image, const PictureStyle& style);

// Draws the picture to `path` (.png, .svg or .pdf), written atomically. Throws
// InputError for inconsistent array sizes or an unknown extension.
void renderLattice(const LatticeImage& image, const PictureStyle& style, const std::string& path);

// Parses a view direction: "x", "-y", "z" or three numbers "1,1,1" (towards the viewer);
// InputError naming `file` and `line` otherwise.
std::array<double, 3> parseView(const std::string& text, const std::string& file = "view",
                                int line = 0);

}  // namespace pdq::post
