// Snooker's jump shot (WPBSA Official Rules of Snooker, Section 2, "Definitions": "Jump Shot"): the
// cue ball passing over an object ball, read from the shot's event log.
#pragma once

#include "rules/shot.h"

namespace pool::rules {

/// Whether the cue ball jumped over an object ball: before it first touched an object ball, its
/// centre's flight (from leaving the slate to landing, bent at the cushions it met in the air)
/// passed within a ball's diameter (2 `ball_radius`) of a ball standing on the table (any part of
/// the cue ball over any part of it) without touching it, or it struck a ball in the air and
/// landed on that ball's far side. Not a jump shot (the Rules' exceptions): whatever the cue ball
/// does after it first touched an object ball on the cloth, and a ball struck in the air that it
/// does not land beyond. Object balls stand where `shot.before` has them until the first contact.
bool jumpedOverABall(const Shot& shot, double ball_radius);

}  // namespace pool::rules
