// Names, intents and log lines of planned shots.
#include "client/bot/ai/planned_shot.h"

#include <cstdio>

namespace pool::bot {

const char* toString(ShotKind kind) {
  switch (kind) {
    case ShotKind::Break:
      return "break";
    case ShotKind::Pot:
      return "pot";
    case ShotKind::Safety:
      return "safety";
    case ShotKind::Fallback:
      return "fallback";
    case ShotKind::Choice:
      return "choice";
    case ShotKind::Carom:
      return "carom";
  }
  return "unknown";
}

rules::Intent intentOf(const PlannedShot& shot) {
  rules::Intent intent;
  if (!shot.calls_pockets) {
    // Snooker: a choice is made before the stroke, never with it.
    if (shot.nominate) intent.ball = shot.called_ball;
    return intent;
  }
  if (shot.called_ball) intent = rules::Intent::call(*shot.called_ball, shot.called_pocket);
  intent.safety = shot.safety;
  intent.choice = shot.choice;
  return intent;
}

bool shoots(const PlannedShot& shot) {
  return !shot.choice || *shot.choice == rules::Choice::PlayOn ||
         *shot.choice == rules::Choice::BallInHand || *shot.choice == rules::Choice::RespotEight ||
         *shot.choice == rules::Choice::PushOut || *shot.choice == rules::Choice::FreeBall;
}

std::string describe(const PlannedShot& shot) {
  char text[200];
  if (!shoots(shot)) {
    std::snprintf(text, sizeof text, "choice %s", rules::toString(*shot.choice));
    return text;
  }
  std::string call = shot.called_ball
                         ? std::to_string(*shot.called_ball) + " in " + shot.called_pocket
                         : std::string(shot.safety ? "safety" : "no call");
  std::snprintf(text, sizeof text, "%s: %s at %.2f m/s (yaw %.4f)", toString(shot.kind),
                call.c_str(), shot.cue.speed, shot.cue.yaw);
  std::string line = text;
  if (shot.cue_ball_at) {
    std::snprintf(text, sizeof text, ", cue ball at (%.3f, %.3f)", shot.cue_ball_at->x(),
                  shot.cue_ball_at->y());
    line += text;
  }
  if (shot.choice) line += std::string(", choosing ") + rules::toString(*shot.choice);
  return line;
}

}  // namespace pool::bot
