// pdq list: the registered models and generators (with --generator NAME, one generator's
// parameters, their defaults and the order of the IDs it gives).
#include <cstdio>

#include "cli/commands.hpp"
#include "engine/model.hpp"
#include "prep/generator.hpp"

namespace pdq::cli {

namespace {
// A description's first line: the rest is the generator's page.
std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }
}  // namespace

void listCommand(const ListOptions& o, bool root) {
  if (!o.generator.empty()) {
    GeneratorRegistry::get(o.generator, "--generator");  // an unknown name is an error
    for (const auto& [name, what] : GeneratorRegistry::list())
      if (name == o.generator && root) std::printf("%s: %s\n", name.c_str(), what.c_str());
    return;
  }
  if (!root) return;
  std::printf("models:\n");
  for (const auto& [name, what] : ModelRegistry::list())
    std::printf("  %-12s %s\n", name.c_str(), firstLine(what).c_str());
  std::printf("particle generators ([particles] generator = ...; pdq list --generator NAME):\n");
  for (const auto& [name, what] : GeneratorRegistry::list())
    std::printf("  %-12s %s\n", name.c_str(), firstLine(what).c_str());
  std::printf("models with a strength spec (pdq strength):\n");
  std::string withSpec;
  for (const auto& [name, what] : ModelRegistry::list())
    if (!ModelRegistry::create(name)->strengthSpec().load.empty()) withSpec += " " + name;
  std::printf(" %s\n", withSpec.empty() ? " (none)" : withSpec.c_str());
}

}  // namespace pdq::cli
