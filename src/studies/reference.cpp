#include "studies/reference.hpp"

#include <map>

#include "studies/mplm_reference.hpp"

namespace pdq {

Reference referenceFor(const Scenario& sc, const Params& model) {
  using Check = Reference (*)(const Params& generator, const Params& model);
  static const std::map<std::string, Check> byGenerator = {{"mplm_plate", mplm::plateReference},
                                                           {"mplm_beam", mplm::beamReference},
                                                           {"mplm3d_beam", mplm::memberReference}};
  const auto it = byGenerator.find(sc.generator);
  return it == byGenerator.end() ? Reference{} : it->second(sc.generatorParams, model);
}

}  // namespace pdq
