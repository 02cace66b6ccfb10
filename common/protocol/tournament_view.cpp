// Names of a tournament's format and phase.
#include "protocol/tournament_view.h"

namespace pool::protocol {

const char* toString(TournamentFormat format) {
  switch (format) {
    case TournamentFormat::SingleElimination:
      return "single";
    case TournamentFormat::DoubleElimination:
      return "double";
    case TournamentFormat::RoundRobin:
      return "round-robin";
  }
  return "unknown";
}

const char* toString(TournamentPhase phase) {
  switch (phase) {
    case TournamentPhase::Entry:
      return "entry";
    case TournamentPhase::Running:
      return "running";
    case TournamentPhase::Finished:
      return "finished";
    case TournamentPhase::Cancelled:
      return "cancelled";
  }
  return "unknown";
}

}  // namespace pool::protocol
