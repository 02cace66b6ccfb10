// Names of match phases.
#include "match/match_types.h"

namespace pool::server {

const char* toString(MatchPhase phase) {
  switch (phase) {
    case MatchPhase::Lobby: return "lobby";
    case MatchPhase::Break: return "break";
    case MatchPhase::Open: return "open";
    case MatchPhase::Assigned: return "assigned";
    case MatchPhase::Over: return "over";
    case MatchPhase::Closed: return "closed";
  }
  return "unknown";
}

}  // namespace pool::server
