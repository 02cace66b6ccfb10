// Distils a checked event log into the facts a referee reads: first contact, cushions, balls down.
#pragma once

#include <string>
#include <vector>

#include "core/result.h"
#include "rules/shot.h"

namespace pool::rules {

/// A ball that dropped.
struct Pocketing {
  int id = 0;
  std::string pocket;
  double t = 0.0;  ///< s from the strike
};

/// What happened on a shot, as the rules need it.
struct ShotFacts {
  int first_contact = -1;  ///< the object ball the cue ball touched first; -1: none
  bool cushion_after_contact =
      false;  ///< a ball (cue or numbered) touched a cushion or jaw at or after the first contact
  bool cue_crossed_head_string =
      false;  ///< an event placed the cue ball at x >= head string before (or at) the first contact
  std::vector<Pocketing> pocketed;  ///< every ball that dropped, cue ball included, in time order
  std::vector<int> off_table;  ///< every ball that left the table, cue ball included, in time order
  std::vector<int> removed;    ///< balls the watchdog took off the table (no Pocket/OffTable event)
  std::vector<int> cushioned;  ///< distinct object balls that touched a cushion or jaw, in order

  bool isPocketed(int id) const;
  bool isOffTable(int id) const;
  bool isRemoved(int id) const;
  /// The pocket ball `id` dropped into; "" if it did not.
  std::string pocketOf(int id) const;
  /// Object balls (1–21) that dropped, in time order.
  std::vector<int> objectBallsPocketed() const;
  /// Object balls (1–21) that left the table, in time order.
  std::vector<int> objectBallsOffTable() const;
  bool cueBallLost() const { return isPocketed(0) || isOffTable(0); }
};

/// Checks the shot (see checkShot) and distils its log. `head_string_x` is the x of the head
/// string (table frame, m).
Result<ShotFacts> distilShot(const Shot& shot, double head_string_x);

}  // namespace pool::rules
