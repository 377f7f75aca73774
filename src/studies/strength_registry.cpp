#include "studies/strength_registry.hpp"

namespace pdq {

template <>
Registry<StrengthDriver>::Table& Registry<StrengthDriver>::table() {
  static Table t{"strength driver", "no strength driver is available for model"};
  return t;
}

}  // namespace pdq
