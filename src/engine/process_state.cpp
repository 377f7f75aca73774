#include "engine/process_state.hpp"

#include <fstream>
#include <iterator>
#include <string>

namespace pdq {

ProcessState processState(int pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  if (!stat) {
    // No /proc at all, or no such process.
    return std::ifstream("/proc/self/stat") ? ProcessState::Gone : ProcessState::Unknown;
  }
  const std::string text{std::istreambuf_iterator<char>(stat), std::istreambuf_iterator<char>()};
  // "pid (command) state ...": the command may itself hold spaces and parentheses.
  const auto close = text.rfind(')');
  if (close == std::string::npos || close + 2 >= text.size()) return ProcessState::Unknown;
  switch (text[close + 2]) {
    case 'T':
    case 't':
      return ProcessState::Stopped;
    case 'Z':
    case 'X':
    case 'x':
      return ProcessState::Gone;
    default:
      return ProcessState::Alive;
  }
}

}  // namespace pdq
