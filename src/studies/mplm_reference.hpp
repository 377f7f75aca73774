#pragma once
// Textbook strengths of the MPLM specimens (generators mplm_plate and mplm_beam), from the
// scenario's own parameters. The concrete's strengths follow the model's calibration
// (thesis Table 4.1 and §4.3.2; docs/mplm.md): f_t = E ε_t (youngs_modulus ×
// tensile_strain) and f'c = 10 f_t; the steel's f_y = E_s ε_y (steel_modulus ×
// steel_yield_strain).
#include <optional>

#include "engine/params.hpp"
#include "models/mplm/common/parameters.hpp"
#include "prep/mplm/generators.hpp"
#include "prep/mplm/generators3d.hpp"
#include "studies/aci318.hpp"
#include "studies/reference.hpp"

namespace pdq::mplm {

struct Strengths {
  double ft = 0, fc = 0;  // concrete: tensile, compressive (Pa)
  double fy = 0, Es = 0;  // steel: yield strength, modulus (Pa)
};
Strengths strengths(const Parameters& par);

// The beam's section for ACI 318: b = thickness, h = depth, d = depth − bar centroid, one
// bar, one stirrup bar per position (the 2D lattice has one).
aci318::Section section(const BeamSpec& b, const Parameters& par);

// Plates: f_t in tension, f'c in compression (MPa). Beams (kN/m): a simply supported
// span's ACI 318 line load (flexure or shear, whichever is lower), or for a plain beam the
// load at which the bending stress reaches f_t; none with supports = "none".
Reference plateReference(const Params& generator, const Params& model);
Reference beamReference(const Params& generator, const Params& model);

// 3D members (mplm3d_beam): b = width, h = depth; the tension steel is the bars on the
// tension side of mid-depth (the top of a cantilever under a downward tip load, the bottom
// of a simply supported beam under a downward load), d from the compression face to their
// centroid; a hoop gives two legs of its bar per spacing. None without tension steel.
std::optional<aci318::Section> section(const mplm3d::BeamSpec& b, const Parameters& par);
// A cantilever under a tip load (N): ACI 318's P = M_n/L or V_n, whichever is lower (L the
// member's length, as the thesis takes it), or for a plain one M_cr/L. A simply supported
// member under the top load (kN/m): as beamReference, with L the member's length. None
// for other supports and loads.
Reference memberReference(const Params& generator, const Params& model);

}  // namespace pdq::mplm
