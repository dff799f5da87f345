#include "radiosity/pipeline/solution.h"

#include "radiosity/core/log.h"

namespace rad {

std::string stopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::Tolerance:
      return "tolerance";
    case StopReason::Bounces:
      return "bounces";
    case StopReason::IterationLimit:
      return "iteration limit";
    case StopReason::TimeLimit:
      return "time limit";
  }
  return "?";
}

void SolveReport::skip(std::string what, std::string why) {
  logInfo("skipped: " + what + " (" + why + ")");
  skipped.push_back({std::move(what), std::move(why)});
}

}  // namespace rad
