// The turn at the window: which seat aims, how its turn opens, and the shots it sends.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>

#include "client/app/controls.h"
#include "client/app/match_session.h"
#include "client/ui/window_notes.h"
#include "game/loaded_table.h"
#include "protocol/shot_request.h"

namespace pool::ui {

/// The seat aiming at this screen and the cue ball it put in hand, kept between frames.
class TurnDesk {
 public:
  /// With `json`, each shot sent is printed as a JSON line.
  TurnDesk(app::MatchSession& session, app::Controls& controls, const game::LoadedTable& table,
           WindowNotes& notes, bool json);

  /// Opens the aim when a seat of this screen comes to shoot (again after a practice table's
  /// layout changed), and stops it when none does.
  void follow();
  /// Sends `request` for the seat aiming, which aims no more; a failure is a note.
  void send(protocol::ShotRequest request);
  /// An answer to the rules' choice: the option of the shot aimed, or a re-rack sent at once.
  void chooseOption(protocol::ShotOption option);
  /// Sends the seat's aim (paced by the session): `stroke` when it is the aim a shot was
  /// released with. Nothing when no seat of this screen aims.
  void sendAim(const app::AimState& aim, const Eigen::Vector3d& cue_ball, bool stroke, double now);
  /// The controls' live aim goes out while a seat of this screen aims.
  void sendLiveAim(double now);
  /// The seat aiming at this screen; -1: none.
  int aimingSeat() const { return aiming_seat_; }
  /// The turn at this screen is over (its aim was stopped).
  void end() { aiming_seat_ = -1; }
  /// The turn is over and a cue ball put in hand is forgotten (a new game).
  void reset();
  /// Where the cue ball is held in hand (aiming), or put for the shot sent (until its frames).
  std::optional<Eigen::Vector3d> cueBallHeld();

 private:
  /// A cue ball put in hand for a shot sent: where, and the shot number that will count it.
  struct Placed {
    Eigen::Vector3d at;
    std::uint32_t shot = 0;
  };

  void start(int shooter, const client::MatchView& view);
  Eigen::Vector3d cueBallOf(const client::MatchView& view) const;

  app::MatchSession& session_;
  app::Controls& controls_;
  const game::LoadedTable& table_;
  WindowNotes& notes_;
  bool json_;
  int aiming_seat_ = -1;
  std::uint32_t aimed_revision_ = 0;  ///< the state the aim started from (practice tables)
  std::optional<Placed> placed_;
};

}  // namespace pool::ui
