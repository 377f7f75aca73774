#include "cli/options.hpp"

#include "engine/error.hpp"

namespace pdq::cli {

void setFromCommandLine(Params& into, const std::vector<std::string>& items) {
  for (const auto& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("command line", 0, "--set '" + item + "' is not key=value");
    into.set(item.substr(0, eq), item.substr(eq + 1), "command line", 0);
  }
}

Params commandLineParams(const std::vector<std::string>& items, const std::string& owner) {
  Params p(owner);
  setFromCommandLine(p, items);
  return p;
}

}  // namespace pdq::cli
