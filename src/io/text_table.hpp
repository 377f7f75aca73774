#pragma once
// Reading the thesis's free-format ASCII files: whitespace-separated numbers, one record
// per line, '#' comments and blank lines ignored. Every problem is reported with the file
// and line (pdq::InputError).
#include <string>
#include <vector>

namespace pdq {

struct TextRecord {
  int line;
  std::vector<double> values;
};

// Reads every record of `path`; each must have `columns` finite numbers (0: any count).
std::vector<TextRecord> readNumberTable(const std::string& path, int columns,
                                        const std::string& columnNames = "");
// The same for `text` already read (`name`: the file named in messages).
std::vector<TextRecord> parseNumberTable(const std::string& text, const std::string& name,
                                         int columns, const std::string& columnNames = "");

// The lines of a text file without comments; throws InputError if it cannot be read.
std::vector<std::pair<int, std::string>> readLines(const std::string& path);

}  // namespace pdq
