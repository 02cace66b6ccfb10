// The sounds a shot's event log asks for: one cue per audible event, in time order.
#pragma once

#include <vector>

#include "client/audio/impact_law.h"
#include "physics/events.h"

namespace pool::audio {

/// One sound to start at a time of the shot.
struct SoundCue {
  double t = 0.0;  ///< s from the strike
  SoundKind kind = SoundKind::BallClick;
  double amplitude = 0.0;   ///< RMS, from the kind's ImpactLaw
  double brightness = 1.0;  ///< frequency scale of the modes
  int ball = 0;             ///< the ball that sounds (picks a variant)
};

/// The kind of sound an event makes, if any: Strike → CueStrike, BallBall → BallClick,
/// BallCushion and Land → CushionThump, Pocket → PocketDrop; other events are silent.
bool soundKindOf(physics::EventType type, SoundKind& kind);

/// Cues for every event loud enough to hear (amplitude > 0), sorted by time (stable).
std::vector<SoundCue> cuesFromEvents(const physics::EventLog& events, const ImpactLaws& laws);

}  // namespace pool::audio
