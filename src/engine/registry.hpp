#pragma once
// A table of named things that register themselves at load time (models, particle
// generators): one line at namespace scope in the file that defines the
// thing, through a macro such as PDQ_REGISTER_MODEL.
//
// A name is registered once. A second registration under the same name is refused (the
// first stays) and every later look-up fails with an error naming both descriptions, so
// two models (or a plugin and a built-in) never silently replace one another.
//
// Each kind has one table, defined in the kind's .cpp file (so a plugin loaded later
// registers into the same table as the pdq command):
//
//     template <> Registry<Factory>::Table& Registry<Factory>::table() {
//       static Table t{"model"};
//       return t;
//     }
//
// T must differ between kinds (each is a distinct std::function signature).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "engine/error.hpp"

namespace pdq {

template <class T>
class Registry {
 public:
  // Registers `item` under `name`; false (and the name marked as conflicting) when the
  // name is taken. Returns a value so that a registration can initialise a static.
  static bool add(const std::string& name, const std::string& description, T item) {
    Table& t = table();
    auto [it, inserted] = t.entries.try_emplace(name, Entry{description, std::move(item)});
    if (!inserted)
      t.conflicts.push_back(t.kind + " '" + name + "' is registered twice (\"" +
                            it->second.description + "\" and \"" + description + "\")");
    return inserted;
  }

  // The item registered under `name`. Throws InputError naming `source` and `line` for an
  // unknown name, suggesting the nearest and listing the known ones.
  static const T& get(const std::string& name, const std::string& source = "", int line = 0) {
    const Table& t = checked();
    auto it = t.entries.find(name);
    if (it == t.entries.end()) {
      std::vector<std::string> names;
      std::string known;
      for (const auto& [n, e] : t.entries) {
        names.push_back(n);
        known += (known.empty() ? "" : ", ") + n;
      }
      throw InputError(source.empty() ? t.kind : source, line,
                       (t.missing.empty() ? "unknown " + t.kind : t.missing) + " '" + name + "'" +
                           suggestion(name, names) +
                           "; known: " + (known.empty() ? "none" : known));
    }
    return it->second.item;
  }

  // (name, description) of every entry, sorted by name.
  static std::vector<std::pair<std::string, std::string>> list() {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& [n, e] : checked().entries) out.emplace_back(n, e.description);
    return out;
  }

  struct Entry {
    std::string description;
    T item;
  };
  struct Table {
    std::string kind;          // "model": "unknown model 'x'", "model 'x' is registered twice"
    std::string missing = "";  // how a failed look-up begins, when not "unknown <kind>"
    std::map<std::string, Entry> entries{};
    std::vector<std::string> conflicts{};
  };

 private:
  static Table& table();  // one per kind, defined in the kind's .cpp

  static const Table& checked() {
    const Table& t = table();
    if (!t.conflicts.empty()) throw Error(t.conflicts.front() + "; each name must be unique");
    return t;
  }
};

}  // namespace pdq
