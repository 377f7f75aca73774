#pragma once
// Out-of-tree models and generators: `--plugin lib.so` loads a shared library built
// against the installed pdq headers (examples/plugin/); its PDQ_REGISTER_MODEL lines
// run as it loads, so its models are known by name before the scenario is read.
#include <string>
#include <vector>

namespace pdq::cli {

// Throws pdq::InputError naming the library and the loader's reason.
void loadPlugins(const std::vector<std::string>& libraries);

}  // namespace pdq::cli
