// The rules module in one include: 8-, 9- and 10-ball (WPA), practice, placement checks and shot
// facts.
#pragma once

#include "rules/ball_groups.h"    // IWYU pragma: export
#include "rules/eight_ball.h"     // IWYU pragma: export
#include "rules/game_rules.h"     // IWYU pragma: export
#include "rules/game_state.h"     // IWYU pragma: export
#include "rules/log_check.h"      // IWYU pragma: export
#include "rules/placement.h"      // IWYU pragma: export
#include "rules/practice.h"       // IWYU pragma: export
#include "rules/respot.h"         // IWYU pragma: export
#include "rules/rotation.h"       // IWYU pragma: export
#include "rules/shot.h"           // IWYU pragma: export
#include "rules/shot_facts.h"     // IWYU pragma: export
#include "rules/table_context.h"  // IWYU pragma: export
#include "rules/verdict.h"        // IWYU pragma: export
