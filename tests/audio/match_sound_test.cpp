// A match between bots over loopback DDS, heard by a SoundBoard fed as the client's loop feeds it:
// every shot sounds from its frames while it plays, and its log, arriving after, adds nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "client/audio/sound_board.h"
#include "client/net/game_client.h"
#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

constexpr auto kSoundDomain = static_cast<Domain>(216);

class MatchSoundTest : public ClientIntegrationTest {};

std::size_t sounded(const audio::SoundBoard& board) {
  return board.mixerStats().started + board.mixerStats().dropped;
}

TEST_F(MatchSoundTest, EveryShotSoundsFromItsFramesAndItsLogAddsNothing) {
  open(kSoundDomain, "sound");
  GameClient listener({kSoundDomain, "", "listener", {}, {}});
  listener.observe("srv-1");  // the first table's states, results and frames, in its partition
  audio::SoundOptions options;
  options.mute = true;  // the silent sink: no device needed, the mixing is the same
  options.log = [](const std::string&) {};
  audio::SoundBoard board(options);
  startServer({});
  startBot("alice", 5);
  startBot("bob", 6);

  // Per shot: the sounds its frames started, and the audible cues of its log.
  std::map<std::uint32_t, std::size_t> from_frames, in_log;
  std::map<std::uint32_t, std::size_t> at_first_frame;
  std::uint32_t current = 0;
  const auto deadline = std::chrono::steady_clock::now() + 120s;
  while (in_log.size() < 4 && std::chrono::steady_clock::now() < deadline) {
    listener.wait(20ms);
    for (auto& event : listener.poll()) {
      if (const auto* f = std::get_if<TableFrame>(&event)) {
        if (f->shot_number != current) {
          current = f->shot_number;
          at_first_frame[current] = sounded(board);
        }
        board.onFrame(f->shot_number, f->sim_time, f->balls);
        board.update(f->sim_time);
      } else if (const auto* r = std::get_if<ShotReport>(&event); r && r->final()) {
        if (!at_first_frame.count(r->shot_number) || in_log.count(r->shot_number)) continue;
        from_frames[r->shot_number] = sounded(board) - at_first_frame[r->shot_number];
        in_log[r->shot_number] = audio::cuesFromEvents(r->events, audio::ImpactLaws{}).size();
        const std::size_t before = sounded(board);
        board.onShot(r->events, r->shot_number);
        board.update(r->events.empty() ? 0.0 : r->events.back().t + 1.0);
        EXPECT_EQ(sounded(board), before) << "shot " << r->shot_number << " sounded twice";
      }
    }
  }
  ASSERT_GE(in_log.size(), 3u) << logs();
  std::size_t frames_total = 0, log_total = 0;
  for (const auto& [shot, n] : in_log) {
    EXPECT_GE(from_frames[shot], 1u) << "shot " << shot << " made no sound (its strike at least)";
    frames_total += from_frames[shot];
    log_total += n;
  }
  std::printf("%zu shots: %zu sounds from their frames, %zu audible events in their logs\n",
              in_log.size(), frames_total, log_total);
  // Frames cannot tell apart every contact inside one sixtieth of a second, but most are heard,
  // and not many more are made up.
  EXPECT_GT(frames_total, log_total / 2);
  EXPECT_LT(frames_total, log_total * 3 / 2);
}

}  // namespace
}  // namespace pool::client::test
