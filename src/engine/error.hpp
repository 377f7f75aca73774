#pragma once
// Errors that stop a run. InputError names the file, line and problem (line 0 when the
// problem is not tied to a line); RunError names the step and the particle.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pdq {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class InputError : public Error {
 public:
  InputError(const std::string& file, int line, const std::string& problem);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& problem() const { return problem_; }  // the message without the place

 private:
  std::string file_;
  int line_;
  std::string problem_;
};

class RunError : public Error {
 public:
  using Error::Error;
};

// The candidate closest to `name` by edit distance, or "" when none is reasonably close;
// used for "unknown parameter 'dT'; did you mean 'dt'?".
std::string nearestName(std::string_view name, const std::vector<std::string>& candidates);

// " (did you mean 'x'?)" or "" — ready to append to a message.
std::string suggestion(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace pdq
