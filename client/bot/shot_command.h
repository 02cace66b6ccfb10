// A planned shot as the command the server receives.
#pragma once

#include "client/bot/ai/planned_shot.h"
#include "protocol/shot_request.h"

namespace pool::bot {

/// The command for `shot` (match, seat, token and sequence are the client's to fill in). A
/// re-racking choice carries a harmless stroke that the server does not play.
protocol::ShotRequest requestOf(const PlannedShot& shot);

}  // namespace pool::bot
