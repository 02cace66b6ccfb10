// Ball numbers and groups of 8-ball.
#include "rules/ball_groups.h"

#include "physics/ball.h"

namespace pool::rules {

const char* toString(Group group) {
  switch (group) {
    case Group::None:
      return "none";
    case Group::Solids:
      return "solids";
    case Group::Stripes:
      return "stripes";
  }
  return "unknown";
}

bool isObjectBall(int id) {
  return id >= 1 && id <= physics::kMaxBallId;
}

Group groupOf(int id) {
  if (id >= 1 && id <= 7) return Group::Solids;
  if (id >= 9 && id <= 15) return Group::Stripes;
  return Group::None;
}

Group otherGroup(Group group) {
  if (group == Group::Solids) return Group::Stripes;
  if (group == Group::Stripes) return Group::Solids;
  return Group::None;
}

}  // namespace pool::rules
