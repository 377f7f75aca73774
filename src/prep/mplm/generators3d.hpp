#pragma once
// The 3D MPLM member generator (model mplm3d), registered as "mplm3d_beam": a box of the
// fcc lattice with supports, loads, monitors, longitudinal bars and closed stirrups, the
// counterpart of the 2D generators (docs/mplm3d.md lists its keys):
//     [particles]
//     generator = "mplm3d_beam"
//     length = 2.0          # X (m)
//     depth = 0.35          # Y, vertical (m)
//     width = 0.16          # Z (m)
//     bonds_along = "x"     # lattice orientation: the axis of one bond direction ...
//     layers_along = "z"    # ... and the axis the close-packed layers are stacked along
//     supports = "clamped"  # clamped | simple | bearings | none
//     clamped_planes = 2    # clamped: planes of particles held at X = 0
//     support_width = 0.04  # simple, bearings: bottom-plane particles this close to an end
//     loading = "tip"       # tip: the last plane at X = length; top: the top plane; none
//     load = 1.0            # tip: total force (N); top: line load (N/m); downward
//     bar_size = "#19"      # longitudinal bars: ASTM size, or bar_diameter (m)
//     bar_count = 2         # in one row at bar_face, bar_cover from it and from the sides
//     bar_face = "bottom"   # top | bottom
//     bar_cover = 0.04      # clear cover to the bars' surface (m)
//     bar_y = [..]          # or each bar's centroid (m), instead of bar_count, bar_face
//     bar_z = [..]          #   and bar_cover
//     stirrup_size = "#13"  # closed rectangular hoops: ASTM size, or stirrup_diameter (m)
//     stirrup_spacing = 0.08
//     stirrup_cover = 0.02  # clear cover to the hoops' outer surface (m)
//     stirrup_first = 0.04  # X of the first hoop (default: half the spacing)
// A plane is every particle within one lattice stride of a face (all rows, all layers).
#include <optional>
#include <string>
#include <vector>

#include "engine/params.hpp"
#include "engine/particle_set.hpp"
#include "prep/fcc.hpp"
#include "prep/rebar.hpp"

namespace pdq::mplm3d {

struct BarSpec {
  double y = 0, z = 0;  // centroid in the section (m)
  prep::BarSection section;
};
struct StirrupSpec {
  prep::BarSection section;
  double spacing = 0, cover = 0, first = 0;
};

struct BeamSpec {
  double length = 2.0, depth = 0.35, width = 0.16;
  ClosePacked lattice;
  std::string supports = "clamped", loading = "tip";
  double load = 1;
  long clampedPlanes = 2;
  double supportWidth = 0.04;
  std::vector<BarSpec> bars;
  std::optional<StirrupSpec> stirrups;
  // The hoops' centre-line rectangle in the section.
  double hoopYLo() const, hoopYHi() const, hoopZLo() const, hoopZHi() const;
};

// The member a generator table describes, every value checked against the box and the
// lattice (InputError naming the key's line: a lattice that does not fit the box, bars
// outside the section, covers over half the section, stirrups closer than s, ...).
BeamSpec beamSpec(const Params& generator, const Params& model);
// Its particles: concrete, then each bar's steel, then each hoop's.
ParticleSet beam(const BeamSpec& spec);

}  // namespace pdq::mplm3d
