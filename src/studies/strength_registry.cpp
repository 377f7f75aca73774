#include "studies/strength_registry.hpp"

#include <map>

#include "engine/error.hpp"

namespace pdq {

namespace {
struct Entry {
  std::string description;
  StrengthRegistry::Driver driver;
};
std::map<std::string, Entry>& registry() {
  static std::map<std::string, Entry> r;
  return r;
}
}  // namespace

bool StrengthRegistry::add(const std::string& model, const std::string& description, Driver d) {
  registry()[model] = Entry{description, std::move(d)};
  return true;
}

const StrengthRegistry::Driver& StrengthRegistry::get(const std::string& model,
                                                      const std::string& source) {
  auto it = registry().find(model);
  if (it == registry().end()) {
    std::string known;
    for (const auto& [n, e] : registry()) known += (known.empty() ? "" : ", ") + n;
    throw InputError(source.empty() ? "strength" : source, 0,
                     "no strength driver is available for model '" + model +
                         "' (models with one: " + (known.empty() ? "none" : known) + ")");
  }
  return it->second.driver;
}

std::vector<std::pair<std::string, std::string>> StrengthRegistry::list() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [n, e] : registry()) out.emplace_back(n, e.description);
  return out;
}

}  // namespace pdq
