// The window's JSON lines on stdout (with --json): shots sent, notes, states and motions.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "client/app/match_session.h"

namespace pool::ui {

/// Prints {"event": "shot", ...}: the shot `request` sent for `seat` of `match` as number `seq`.
void printShotLine(const std::string& match, int seat, std::uint32_t seq,
                   const protocol::ShotRequest& request);

/// Prints {"event": "note", "text", "problem"}.
void printNoteLine(const app::SessionNote& note);

/// Prints {"event": "hud", "texts": [...]}: every text the HUD drew in a frame.
void printHudLine(const std::vector<std::string>& texts);

/// The cue stick as drawn: its tip's face and butt's end, table frame (m) and pixels from the
/// top-left corner.
struct CueStick {
  Eigen::Vector3d tip = Eigen::Vector3d::Zero();
  Eigen::Vector3d butt = Eigen::Vector3d::Zero();
  Eigen::Vector2d tip_px = Eigen::Vector2d::Zero();
  Eigen::Vector2d butt_px = Eigen::Vector2d::Zero();
};

/// The stored shot a frame draws (its replay from the lobby).
struct StoredDrawn {
  std::string match;
  std::uint32_t shot = 0;
  std::uint32_t shots = 0;           ///< the match's stored shots
  double time = 0.0;                 ///< s since its strike (negative before it)
  bool at_rest = false;              ///< its last frame (the table at rest) is drawn
  std::vector<physics::Ball> balls;  ///< as drawn
};

/// One frame as drawn (--log-frames).
struct DrawnFrame {
  double now = 0.0;                   ///< s on the window's clock
  std::optional<std::uint32_t> shot;  ///< the shot whose frames were played last
  bool moving = false;                ///< a shot's motion is being drawn
  double play_time = 0.0;             ///< s since that shot's strike, as played back
  bool aiming = false;
  bool dragging = false;                  ///< the cue ball in hand under the mouse
  bool replaying = false;                 ///< the instant replay is drawn
  double replay_time = 0.0;               ///< s since the replayed shot's strike
  std::string quality;                    ///< the drawing preset: high, full or light
  std::optional<Eigen::Vector3d> cue;     ///< the cue ball as drawn, table frame (m)
  std::optional<Eigen::Vector2d> cue_px;  ///< and in pixels from the top-left corner (not when
                                          ///< behind the eye)
  Eigen::Vector2d mouse = Eigen::Vector2d::Zero();
  std::array<float, 16> view{};        ///< column after column
  std::array<float, 16> projection{};  ///< column after column
  int width = 0;
  int height = 0;
  std::optional<CueStick> cue_stick;  ///< the cue, when one was drawn
  std::string cue_source;             ///< whose: "local", "remote" (a live aim) or "stroke"
  std::optional<protocol::AimSample> live_aim;  ///< the latest live aim shown (unsmoothed)
  std::uint64_t aim_dropped = 0;                ///< live aims dropped so far
  std::string capture;  ///< the PNG file this frame is written to (a script's capture step)
  std::optional<StoredDrawn> stored;  ///< a stored shot's replay is drawn
};

/// Prints {"event": "drawn", ...}.
void printDrawnLine(const DrawnFrame& frame);

/// Prints a line for each new state of the match followed and each shot whose motion starts.
class ProgressLog {
 public:
  /// Prints what is new in `session` since the last call.
  void report(const app::MatchSession& session);

 private:
  std::optional<std::uint32_t> last_revision_;
  std::optional<std::uint32_t> last_motion_;
};

}  // namespace pool::ui
