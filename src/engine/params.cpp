#include "engine/params.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "engine/error.hpp"

namespace pdq {

std::string numberText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void Params::set(const std::string& key, std::string text, std::string file, int line) {
  values_[key] = Value{std::move(text), std::move(file), line};
}

bool Params::has(const std::string& key) const {
  asked_.push_back(key);
  return values_.count(key) != 0;
}

std::optional<Params::Value> Params::raw(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end()) return std::nullopt;
  used_[key] = true;
  return it->second;
}

const Params::Value& Params::get(const std::string& key) const {
  asked_.push_back(key);
  auto it = values_.find(key);
  if (it == values_.end()) {
    // A key given but not read that is close to this one is the likely typo.
    std::vector<std::string> unread;
    for (const auto& [k, v] : values_)
      if (!used_.count(k)) unread.push_back(k);
    if (const std::string near = nearestName(key, unread); !near.empty()) {
      const Value& v = values_.at(near);
      throw InputError(v.file, v.line,
                       "unknown parameter '" + near + "' for " + owner_ + " (did you mean '" + key +
                           "'? it is missing)");
    }
    std::string file = values_.empty() ? owner_ : values_.begin()->second.file;
    throw InputError(file, 0, "missing parameter '" + key + "' for " + owner_);
  }
  used_[key] = true;
  return it->second;
}

void Params::bad(const Value& v, const std::string& key, const std::string& why) const {
  throw InputError(v.file, v.line, "parameter '" + key + "' of " + owner_ + ": " + why);
}

static bool parseDouble(const std::string& s, double& out) {
  const char* b = s.data();
  const char* e = s.data() + s.size();
  while (b < e && (*b == ' ' || *b == '\t')) ++b;
  while (e > b && (e[-1] == ' ' || e[-1] == '\t')) --e;
  if (b < e && *b == '+') ++b;
  auto [p, ec] = std::from_chars(b, e, out);
  return ec == std::errc() && p == e;
}

double Params::number(const std::string& key) const {
  const Value& v = get(key);
  double d = 0;
  if (!parseDouble(v.text, d)) bad(v, key, "'" + v.text + "' is not a number");
  if (!std::isfinite(d)) bad(v, key, "'" + v.text + "' is not finite");
  return d;
}

double Params::number(const std::string& key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

template <class T>
T Params::within(const std::string& key, T v, T lo, T hi) const {
  if (v < lo || v > hi) {
    std::ostringstream os;
    os << v << " is outside [" << lo << ", " << hi << "]";
    bad(values_.at(key), key, os.str());
  }
  return v;
}

double Params::number(const std::string& key, double fallback, double lo, double hi) const {
  return has(key) ? within(key, number(key), lo, hi) : fallback;
}

long Params::integer(const std::string& key) const {
  const Value& v = get(key);
  double d = 0;
  if (!parseDouble(v.text, d) || d != std::floor(d) || std::fabs(d) > 9.0e15)
    bad(v, key, "'" + v.text + "' is not a whole number");
  return static_cast<long>(d);
}

long Params::integer(const std::string& key, long fallback) const {
  return has(key) ? integer(key) : fallback;
}

long Params::integer(const std::string& key, long fallback, long lo, long hi) const {
  return has(key) ? within(key, integer(key), lo, hi) : fallback;
}

std::string Params::text(const std::string& key) const { return get(key).text; }

std::string Params::text(const std::string& key, const std::string& fallback) const {
  return has(key) ? text(key) : fallback;
}

bool Params::flag(const std::string& key, bool fallback) const {
  if (!has(key)) return fallback;
  const Value& v = get(key);
  if (v.text == "true" || v.text == "1" || v.text == "yes" || v.text == "on") return true;
  if (v.text == "false" || v.text == "0" || v.text == "no" || v.text == "off") return false;
  bad(v, key, "'" + v.text + "' is not true or false");
}

std::vector<double> Params::numbers(const std::string& key) const {
  const Value& v = get(key);
  std::vector<double> out;
  std::istringstream in(v.text);
  std::string item;
  while (in >> item) {
    double d = 0;
    if (!parseDouble(item, d) || !std::isfinite(d))
      bad(v, key, "'" + item + "' is not a finite number");
    out.push_back(d);
  }
  return out;
}

std::string Params::choice(const std::string& key, const std::string& fallback,
                           const std::vector<std::string>& choices) const {
  if (!has(key)) return fallback;
  const Value& v = get(key);
  for (const auto& c : choices)
    if (c == v.text) return c;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  bad(v, key, "'" + v.text + "' is not one of " + list + suggestion(v.text, choices));
}

void Params::accept(const std::string& key) const {
  asked_.push_back(key);
  if (values_.count(key)) used_[key] = true;
}

std::vector<std::string> Params::keys() const {
  std::vector<std::string> k;
  for (const auto& [key, v] : values_) k.push_back(key);
  return k;
}

std::vector<std::string> Params::knownKeys() const { return asked_; }

void Params::checkAllUsed() const {
  for (const auto& [key, v] : values_) {
    if (used_.count(key)) continue;
    throw InputError(v.file, v.line,
                     "unknown parameter '" + key + "' for " + owner_ + suggestion(key, asked_));
  }
}

}  // namespace pdq
