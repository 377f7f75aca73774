#pragma once
// Named parameters read from a scenario's TOML table or a thesis .dat file. Each value
// remembers where it was written, every read is recorded, and checkAllUsed() turns a
// parameter nobody asked for into an error that names its file and line and suggests
// the nearest known name.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pdq {

// A number as text that reads back as the same double (%.17g): how numbers are written into
// parameters, input files and tables.
std::string numberText(double v);

class Params {
 public:
  struct Value {
    std::string text;  // numbers and words as written; arrays as space-separated items
    std::string file;
    int line = 0;
  };

  explicit Params(std::string owner = "parameters") : owner_(std::move(owner)) {}

  void set(const std::string& key, std::string text, std::string file = "", int line = 0);
  bool has(const std::string& key) const;
  const std::string& owner() const { return owner_; }

  // Required values: a missing key is an error naming the owner.
  double number(const std::string& key) const;
  long integer(const std::string& key) const;
  std::string text(const std::string& key) const;
  // Optional values with a default; range-checked when bounds are given.
  double number(const std::string& key, double fallback) const;
  double number(const std::string& key, double fallback, double lo, double hi) const;
  long integer(const std::string& key, long fallback) const;
  long integer(const std::string& key, long fallback, long lo, long hi) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  bool flag(const std::string& key, bool fallback) const;
  std::vector<double> numbers(const std::string& key) const;
  // One of `choices` (error lists them and suggests the nearest).
  std::string choice(const std::string& key, const std::string& fallback,
                     const std::vector<std::string>& choices) const;

  // Declares keys that are known but read elsewhere, so checkAllUsed accepts them.
  void accept(const std::string& key) const;
  std::vector<std::string> keys() const;
  std::vector<std::string> knownKeys() const;
  // Throws InputError for the first parameter never read or accepted.
  void checkAllUsed() const;
  std::optional<Value> raw(const std::string& key) const;

 private:
  const Value& get(const std::string& key) const;
  [[noreturn]] void bad(const Value& v, const std::string& key, const std::string& why) const;
  // v, or an error naming the key's file and line when v is outside [lo, hi].
  template <class T>
  T within(const std::string& key, T v, T lo, T hi) const;
  std::string owner_;
  std::map<std::string, Value> values_;
  mutable std::map<std::string, bool> used_;
  mutable std::vector<std::string> asked_;  // every key asked for, present or not
};

}  // namespace pdq
