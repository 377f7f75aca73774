#pragma once
// The close-packed hexagonal lattice of thesis Fig. 4.1 filling a rectangle, in either of
// the two orientations of §4.4.1: rows of particles at spacing s along X with rows
// (√3/2)s apart (bonds along X), or the same rotated by 90° (bonds along Y).
#include <array>
#include <string>
#include <vector>

namespace pdq::prep {

enum class HexOrientation { BondsAlongX, BondsAlongY };

// "x" or "y" (throws std::invalid_argument otherwise).
HexOrientation hexOrientation(const std::string& name);

// Lattice points in [x0, x0+lx] × [y0, y0+ly] (boundaries included up to 1e-9 s), one
// corner particle at (x0, y0), ordered row by row (X orientation) or column by column.
std::vector<std::array<double, 2>> hexagonalRectangle(double lx, double ly, double s,
                                                      HexOrientation o, double x0 = 0,
                                                      double y0 = 0);

// Distance between rows (X orientation) or columns (Y orientation): (√3/2) s.
double hexPitch(double s);
// How many points hexagonalRectangle makes, counted without making them.
double hexagonalRectangleCount(double lx, double ly, double s, HexOrientation o);

}  // namespace pdq::prep
