#include "io/text_table.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "engine/error.hpp"

namespace pdq {

std::vector<std::pair<int, std::string>> readLines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the file (missing or unreadable)");
  std::vector<std::pair<int, std::string>> out;
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    const auto hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    out.emplace_back(n, line);
  }
  return out;
}

std::vector<TextRecord> readNumberTable(const std::string& path, int columns,
                                        const std::string& columnNames) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the file (missing or unreadable)");
  std::stringstream ss;
  ss << in.rdbuf();
  return parseNumberTable(ss.str(), path, columns, columnNames);
}

std::vector<TextRecord> parseNumberTable(const std::string& text, const std::string& path,
                                         int columns, const std::string& columnNames) {
  std::vector<TextRecord> out;
  const char* p = text.data();
  const char* end = p + text.size();
  int line = 0;
  while (p < end) {
    ++line;
    const char* eol = p;
    while (eol < end && *eol != '\n') ++eol;
    const char* stop = p;
    while (stop < eol && *stop != '#') ++stop;
    TextRecord rec{line, {}};
    const char* q = p;
    while (true) {
      while (q < stop && (*q == ' ' || *q == '\t' || *q == '\r' || *q == ',')) ++q;
      if (q >= stop) break;
      const char* tokEnd = q;
      while (tokEnd < stop && *tokEnd != ' ' && *tokEnd != '\t' && *tokEnd != '\r' &&
             *tokEnd != ',')
        ++tokEnd;
      double v = 0;
      const char* b = q;
      if (*b == '+') ++b;
      auto [ptr, ec] = std::from_chars(b, tokEnd, v);
      const std::string tok(q, tokEnd);
      if (ec != std::errc() || ptr != tokEnd)
        throw InputError(
            path, line,
            "'" + tok + "' is not a number (column " + std::to_string(rec.values.size() + 1) + ")");
      if (!std::isfinite(v))
        throw InputError(path, line,
                         "'" + tok + "' is not a finite number (column " +
                             std::to_string(rec.values.size() + 1) + ")");
      rec.values.push_back(v);
      q = tokEnd;
    }
    if (!rec.values.empty()) {
      if (columns > 0 && static_cast<int>(rec.values.size()) != columns) {
        std::string msg = "expected " + std::to_string(columns) + " numbers";
        if (!columnNames.empty()) msg += " (" + columnNames + ")";
        msg += ", found " + std::to_string(rec.values.size());
        throw InputError(path, line, msg);
      }
      out.push_back(std::move(rec));
    }
    p = eol + 1;
  }
  return out;
}

}  // namespace pdq
