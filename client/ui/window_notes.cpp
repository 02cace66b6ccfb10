// The window's notes: a few lines kept for the HUD, each printed as it comes with --json.
#include "client/ui/window_notes.h"

#include "client/ui/window_log.h"

namespace pool::ui {
namespace {

constexpr std::size_t kNotesShown = 6;

}  // namespace

void WindowNotes::add(app::SessionNote note) {
  if (json_) printNoteLine(note);
  notes_.push_back(std::move(note));
  while (notes_.size() > kNotesShown) notes_.pop_front();
}

}  // namespace pool::ui
