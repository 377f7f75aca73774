#include "post/table.hpp"

#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "engine/error.hpp"

namespace pdq::post {
namespace {

std::vector<std::string> split(std::string line) {
  std::replace(line.begin(), line.end(), ',', ' ');
  std::replace(line.begin(), line.end(), '\t', ' ');
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

bool number(const std::string& w, double& v) {
  const char* end = w.data() + w.size();
  auto [p, ec] = std::from_chars(w.data(), end, v);
  if (ec == std::errc() && p == end) return true;
  // from_chars rejects a leading '+' and words such as "nan" / "inf" written by streams.
  try {
    std::size_t used = 0;
    v = std::stod(w, &used);
    return used == w.size();
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

const std::vector<double>& Table::column(const std::string& name) const {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw InputError(source, 0, "no column '" + name + "'" + suggestion(name, names));
  return columns[it - names.begin()];
}

Table readTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open the file");
  Table t;
  t.source = path;
  std::vector<std::string> lastComment;
  std::string line;
  int lineNo = 0;
  bool started = false;
  while (std::getline(in, line)) {
    ++lineNo;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (line[first] == '#') {
      if (!started) lastComment = split(line.substr(first + 1));
      continue;
    }
    const std::vector<std::string> words = split(line);
    std::vector<double> row(words.size());
    bool numeric = true;
    for (std::size_t k = 0; k < words.size() && numeric; ++k) numeric = number(words[k], row[k]);
    if (!started) {
      started = true;
      t.columns.resize(words.size());
      if (!numeric) {  // a header line
        t.names = words;
        continue;
      }
      if (lastComment.size() == words.size()) t.names = lastComment;
      for (std::size_t k = t.names.size(); k < words.size(); ++k)
        t.names.push_back(std::to_string(k + 1));
    }
    if (words.size() != t.columns.size())
      throw InputError(path, lineNo,
                       "expected " + std::to_string(t.columns.size()) + " values, found " +
                           std::to_string(words.size()));
    if (!numeric) {
      for (const std::string& w : words)
        if (double v; !number(w, v)) throw InputError(path, lineNo, "'" + w + "' is not a number");
    }
    for (std::size_t k = 0; k < row.size(); ++k) t.columns[k].push_back(row[k]);
  }
  if (t.rows() == 0) throw InputError(path, 0, "no rows of numbers");
  return t;
}

}  // namespace pdq::post
