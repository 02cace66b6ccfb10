// One entry of a tournament's log of calls (start, report, forfeit, cancel), replayed by fromJson.
#pragma once

#include <cstdint>

namespace pool::tournament {

struct Event {
  enum class Kind : std::uint8_t { Start, Report, Forfeit, Cancel };
  Kind kind = Kind::Start;
  int match = -1;    ///< Start, Report
  int entrant = -1;  ///< Report: the winner; Forfeit: who left
  int racksA = 0;    ///< Report
  int racksB = 0;
};

}  // namespace pool::tournament
