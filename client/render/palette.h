// Colours of the table's and the hall's materials and of the balls (linear RGB, 0..1).
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "table/table_spec.h"

namespace pool::render {

/// How a ball looks: a solid colour, or white with a band of `colour` (stripes, 9–15), and the
/// number on it.
struct BallLook {
  glm::vec3 colour;
  bool striped = false;
  int number = 0;  ///< the number printed on it (0: none)
};

/// The balls a table is played with: a pool set (the cue ball and 1-15, numbered), a carom set
/// (0 the white, 1 the yellow, 2 the red, no numbers) or a snooker set (0 the cue ball, 1–15 the
/// reds, 16 yellow, 17 green, 18 brown, 19 blue, 20 pink, 21 black, no numbers).
enum class BallSet { Pool, Carom, Snooker };

/// The set of a table: snooker balls on a table with snooker marks, carom balls on a table
/// without pockets, else pool balls.
BallSet ballSetOf(const table::TableSpec& spec);

/// The highest ball id of `set` (pool 15, carom 2, snooker 21); 0 is the cue ball in each.
int maxBallIdOf(BallSet set);

/// The look of ball `id` of `set` (pool: 0 the cue ball, 1–15 the object balls); an id the set
/// has not is drawn white.
BallLook ballLook(int id, BallSet set = BallSet::Pool);

/// How a table mesh part looks: its colour and the scene shader's material (shaders::Material).
struct PartLook {
  glm::vec3 colour;
  int material = 0;
};

/// The look of a table mesh part by its name (slate, cushion_*, jaw_*, rail_*, pocket_*, trough:
/// the cabinet under the slate, wooden).
PartLook partLook(const std::string& part_name);

/// The look of a part of the hall (hall_room.h) or of a table's dressing (table_dressing.h) by
/// its name; an unknown name is drawn a neutral grey.
PartLook hallPartLook(const std::string& part_name);

/// The chalk of a snooker table's baulk line, D and spots (chalk_marks.h), mixed into the felt.
glm::vec3 chalkColour();

/// The wood of the rails and cabinet.
glm::vec3 woodColour();
/// Lamp shades (enamel, seen lit from inside) and bulbs.
glm::vec3 shadeColour();
glm::vec3 bulbColour();

}  // namespace pool::render
