#include "engine/timers.hpp"

namespace pdq {

const char* phaseName(Phase p) {
  switch (p) {
    case Phase::Setup:
      return "setup";
    case Phase::Force:
      return "force";
    case Phase::Integrate:
      return "integrate";
    case Phase::Communication:
      return "communication";
    case Phase::Shuffle:
      return "shuffle";
    case Phase::Output:
      return "output";
    case Phase::Other:
      return "other";
    default:
      return "?";
  }
}

}  // namespace pdq
