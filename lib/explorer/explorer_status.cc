#include "explorer/explorer_status.h"

namespace stereonav {

const char* phaseName(ExplorerPhase phase) {
  switch (phase) {
    case ExplorerPhase::kLookingAround: return "looking_around";
    case ExplorerPhase::kTurning: return "turning";
    case ExplorerPhase::kDriving: return "driving";
    case ExplorerPhase::kLookingAtFrontier: return "looking_at_frontier";
    case ExplorerPhase::kEscaping: return "escaping";
    case ExplorerPhase::kBackingOff: return "backing_off";
    case ExplorerPhase::kFinished: return "finished";
  }
  return "?";
}

}  // namespace stereonav
