// The window's notes: the last few lines it tells the player, printed as JSON lines with --json.
#pragma once

#include <deque>

#include "client/app/match_session.h"

namespace pool::ui {

/// The notes the HUD shows, newest last; each one added is also printed with --json.
class WindowNotes {
 public:
  explicit WindowNotes(bool json) : json_(json) {}

  /// Adds `note`, dropping the oldest beyond the few shown.
  void add(app::SessionNote note);
  const std::deque<app::SessionNote>& shown() const { return notes_; }

 private:
  bool json_;
  std::deque<app::SessionNote> notes_;
};

}  // namespace pool::ui
