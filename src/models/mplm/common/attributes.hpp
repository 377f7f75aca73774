#pragma once
// What opens every MPLM particle's row in 2D and 3D: the fixed attributes after the
// reference position, the materials and the interaction state. Each dimension's
// attributes.hpp continues the fixed row from N_SHARED_FIXED.
#include <string>
#include <vector>

namespace pdq::mplm {
inline namespace attributes {

enum SharedFixed {
  FX_X = 0,
  FX_Y,
  FX_Z,           // reference position
  MATERIAL,       // Material below
  BAR,            // steel: which bar (particles of different bars never interact)
  LINK,           // steel: 1 if bonded to the concrete around it (every other one)
  AREA,           // steel: bar cross-section A_s (m²)
  SECOND_MOMENT,  // steel: bar I_s (m⁴)
  CONSTRAINT,     // bit mask of prescribed DOFs (each dimension's Constraint)
  N_SHARED_FIXED
};
// Per-interaction state (each interaction is stored on both particles and evolves alike).
enum BondAttr { OMEGA_T = 0, OMEGA_C, PLASTIC, N_BOND };

enum Material { CONCRETE = 0, STEEL = 1 };

inline bool isSteel(const double* fixedRow) { return fixedRow[MATERIAL] == double(STEEL); }

// The names of the fixed attributes after the position: the shared ones, then `own`.
inline std::vector<std::string> fixedNames(const std::vector<std::string>& own) {
  std::vector<std::string> names{"material", "bar", "link", "area", "second_moment", "constraint"};
  names.insert(names.end(), own.begin(), own.end());
  return names;
}
inline std::vector<std::string> bondNames() { return {"omega_t", "omega_c", "plastic"}; }

}  // namespace attributes
}  // namespace pdq::mplm
