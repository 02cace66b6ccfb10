// Ball numbers and groups of 8-ball: solids 1–7, stripes 9–15, and the 8 on its own.
#pragma once

#include <cstdint>

namespace pool::rules {

constexpr int kEightBall = 8;

/// A player's group. None: not yet assigned (open table), or a ball of no group (cue, 8).
enum class Group : std::uint8_t { None, Solids, Stripes };

const char* toString(Group group);  ///< "none", "solids", "stripes"

/// True for every ball but the cue ball: pool's numbered balls 1–15, snooker's reds and colours
/// (16–21).
bool isObjectBall(int id);

/// Solids for 1–7, Stripes for 9–15, None for the cue ball, the 8 and anything else.
Group groupOf(int id);

/// Solids <-> Stripes; None stays None.
Group otherGroup(Group group);

}  // namespace pool::rules
