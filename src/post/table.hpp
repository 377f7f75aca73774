#pragma once
// Columns of numbers from a text table (time histories, load-displacement CSV files), to
// plot with plotLines. Values are separated by whitespace or commas; lines starting with
// '#' are comments. The column names are the first line if it is not numeric, else the
// last comment line before the data that has one word per column; else "1", "2", ...
#include <string>
#include <vector>

namespace pdq::post {

struct Table {
  std::string source;
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;

  std::size_t rows() const { return columns.empty() ? 0 : columns[0].size(); }
  // Throws InputError naming the file and suggesting the nearest column name.
  const std::vector<double>& column(const std::string& name) const;
};

// Throws InputError naming the file and line for a row of the wrong width or a value
// that is not a number, and for a missing or empty file.
Table readTable(const std::string& path);

}  // namespace pdq::post
