// pool-sound: a scene's shot run through the physics, its sound mixed to a WAV and/or played.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>

#include "client/audio/offline_render.h"
#include "client/audio/sound_board.h"
#include "client/audio/wav_file.h"
#include "scenario/scenario.h"

namespace {

using namespace pool;

struct Flags {
  std::string scene;
  std::string wav;
  bool play = false;
  bool mute = false;
  double seconds = 0.0;  // 0: the whole shot
};

/// Plays the events in real time through a SoundBoard, as the client's loop would.
void play(const physics::EventLog& events, const Flags& flags, double length) {
  audio::SoundOptions options;
  options.mute = flags.mute;
  audio::SoundBoard board(options);
  board.onShot(events);  // no shot number: it sounds from the first update
  const double until = flags.seconds > 0.0 ? std::min(flags.seconds, length) : length;
  const auto start = std::chrono::steady_clock::now();
  for (;;) {
    const double t =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    board.update(t);
    if (t >= until) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(8));
  }
  std::printf("played %llu sounds (%llu dropped) on %s\n",
              static_cast<unsigned long long>(board.mixerStats().started),
              static_cast<unsigned long long>(board.mixerStats().dropped),
              board.outputName().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  Flags flags;
  CLI::App app{"pool-sound: the sound of a scene's shot (assets/scenes/<name>.json or a file)"};
  app.add_option("scene", flags.scene, "scene name (break, bank, ...) or scenario file")
      ->required();
  app.add_option("-o,--wav", flags.wav, "write the mixed sound to this WAV file");
  app.add_flag("--play", flags.play, "play the shot in real time (silently if there is no device)");
  app.add_flag("--mute", flags.mute, "with --play: open no device");
  app.add_option("--seconds", flags.seconds, "with --play: stop after this many seconds")
      ->check(CLI::NonNegativeNumber);
  CLI11_PARSE(app, argc, argv);
  if (flags.wav.empty() && !flags.play) {
    std::fprintf(stderr, "pool-sound: nothing to do: give --wav FILE and/or --play\n");
    return 2;
  }

  auto scene = scenario::loadScenario(flags.scene);
  if (!scene) {
    std::fprintf(stderr, "pool-sound: %s\n", scene.error().c_str());
    return 1;
  }
  auto outcome = scenario::runScenario(*scene);
  if (!outcome) {
    std::fprintf(stderr, "pool-sound: %s\n", outcome.error().c_str());
    return 1;
  }

  // The offline mix: every sound at its exact sample.
  const audio::SoundBank bank;
  const auto cues = audio::cuesFromEvents(outcome->events, audio::ImpactLaws{});
  const auto mixed = audio::renderCues(cues, bank);
  const double length = static_cast<double>(mixed.samples.size()) / bank.rate();
  std::printf(
      "%s: %zu events, %zu sounds, %.2f s, peak %.3f (%.3f before the limiter), "
      "%d voices at most, %llu stolen, %llu dropped\n",
      flags.scene.c_str(), outcome->events.size(), cues.size(), length, mixed.stats.peak_out,
      mixed.stats.peak_in, mixed.stats.max_active,
      static_cast<unsigned long long>(mixed.stats.stolen),
      static_cast<unsigned long long>(mixed.stats.dropped));
  if (!flags.wav.empty()) {
    auto written = audio::writeWav(flags.wav, mixed.samples, bank.rate());
    if (!written) {
      std::fprintf(stderr, "pool-sound: %s\n", written.error().c_str());
      return 1;
    }
    std::printf("wrote %s (%zu bytes)\n", flags.wav.c_str(), *written);
  }
  if (flags.play) play(outcome->events, flags, length);
  return 0;
}
