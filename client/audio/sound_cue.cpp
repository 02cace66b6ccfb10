// Turns a shot's physics events into the sounds they make.
#include "client/audio/sound_cue.h"

#include <algorithm>
#include <cmath>

namespace pool::audio {

bool soundKindOf(physics::EventType type, SoundKind& kind) {
  using physics::EventType;
  switch (type) {
    case EventType::Strike:
      kind = SoundKind::CueStrike;
      return true;
    case EventType::BallBall:
      kind = SoundKind::BallClick;
      return true;
    case EventType::BallCushion:
    case EventType::Land:
      kind = SoundKind::CushionThump;
      return true;
    case EventType::Pocket:
      kind = SoundKind::PocketDrop;
      return true;
    default:
      return false;
  }
}

std::vector<SoundCue> cuesFromEvents(const physics::EventLog& events, const ImpactLaws& laws) {
  std::vector<SoundCue> cues;
  cues.reserve(events.size());
  for (const auto& e : events) {
    SoundKind kind{};
    if (!soundKindOf(e.type, kind) || !std::isfinite(e.t)) continue;
    const ImpactLaw& law = laws.of(kind);
    // Pocket drops carry no speed: they sound at the fall into the liner.
    const double speed = kind == SoundKind::PocketDrop ? laws.pocket_fall_speed : e.speed;
    const double amplitude = law.amplitude(speed);
    if (amplitude <= 0.0) continue;
    cues.push_back({e.t, kind, amplitude, law.brightness(speed), e.ball_a});
  }
  std::stable_sort(cues.begin(), cues.end(),
                   [](const SoundCue& a, const SoundCue& b) { return a.t < b.t; });
  return cues;
}

}  // namespace pool::audio
