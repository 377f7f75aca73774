#pragma once
// `--set key=value` items of the command line as Params (file "command line").
#include <string>
#include <vector>

#include "engine/params.hpp"

namespace pdq::cli {

Params commandLineParams(const std::vector<std::string>& items, const std::string& owner);
// Adds the items to `into`, replacing values of the same keys.
void setFromCommandLine(Params& into, const std::vector<std::string>& items);

}  // namespace pdq::cli
