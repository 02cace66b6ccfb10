// Constructors of a shooter's intent.
#include "rules/shot.h"

#include <utility>

namespace pool::rules {

Intent Intent::call(int ball, std::string pocket) {
  Intent intent;
  intent.ball = ball;
  intent.pocket = std::move(pocket);
  return intent;
}

Intent Intent::safe() {
  Intent intent;
  intent.safety = true;
  return intent;
}

}  // namespace pool::rules
