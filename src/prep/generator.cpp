#include "prep/generator.hpp"

#include <map>

#include "engine/error.hpp"

namespace pdq {

namespace {
struct Entry {
  std::string description;
  GeneratorRegistry::Generator generator;
};
std::map<std::string, Entry>& registry() {
  static std::map<std::string, Entry> r;
  return r;
}
}  // namespace

bool GeneratorRegistry::add(const std::string& name, const std::string& description, Generator g) {
  registry()[name] = Entry{description, std::move(g)};
  return true;
}

const GeneratorRegistry::Generator& GeneratorRegistry::get(const std::string& name,
                                                           const std::string& source, int line) {
  auto it = registry().find(name);
  if (it == registry().end()) {
    std::vector<std::string> names;
    std::string known;
    for (const auto& [n, e] : registry()) {
      names.push_back(n);
      known += (known.empty() ? "" : ", ") + n;
    }
    throw InputError(source.empty() ? "generator" : source, line,
                     "unknown generator '" + name + "'" + suggestion(name, names) +
                         "; known: " + (known.empty() ? "none" : known));
  }
  return it->second.generator;
}

std::vector<std::pair<std::string, std::string>> GeneratorRegistry::list() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [n, e] : registry()) out.emplace_back(n, e.description);
  return out;
}

}  // namespace pdq
