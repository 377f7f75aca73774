#include "engine/model.hpp"

#include <map>

#include "engine/error.hpp"

namespace pdq {

namespace {
struct Entry {
  std::string description;
  ModelRegistry::Factory factory;
};
std::map<std::string, Entry>& registry() {
  static std::map<std::string, Entry> r;
  return r;
}
}  // namespace

bool ModelRegistry::add(const std::string& name, const std::string& description, Factory f) {
  registry()[name] = Entry{description, std::move(f)};
  return true;
}

std::unique_ptr<Model> ModelRegistry::create(const std::string& name, const std::string& source,
                                             int line) {
  auto it = registry().find(name);
  if (it == registry().end()) {
    std::vector<std::string> names;
    for (const auto& [n, e] : registry()) names.push_back(n);
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw InputError(
        source.empty() ? "model" : source, line,
        "unknown model '" + name + "'" + suggestion(name, names) + "; known: " + known);
  }
  return it->second.factory();
}

std::vector<std::pair<std::string, std::string>> ModelRegistry::list() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [n, e] : registry()) out.emplace_back(n, e.description);
  return out;
}

}  // namespace pdq
