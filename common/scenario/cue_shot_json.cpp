// A cue shot's six fields as JSON.
#include "scenario/cue_shot_json.h"

namespace pool::scenario {

nlohmann::json cueShotJson(const physics::CueShot& shot) {
  return {{"yaw", shot.yaw},
          {"tip_side", shot.tip_side},
          {"tip_height", shot.tip_height},
          {"elevation", shot.elevation},
          {"speed", shot.speed},
          {"speed_is_ball", shot.speed_is_ball}};
}

}  // namespace pool::scenario
