// The client's input vocabulary, free of any windowing library: keys, modifiers, mouse buttons.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace pool::app {

/// The keys the controls react to.
enum class Key : std::uint8_t {
  Left,
  Right,
  Up,
  Down,
  Space,
  A,    ///< raise the cue
  Z,    ///< lower the cue
  S,    ///< zoom in
  X,    ///< zoom out
  G,    ///< aim line on/off
  V,    ///< direction vectors on/off
  C,    ///< next called pocket
  K,    ///< declare a safety on/off
  P,    ///< wireframe
  T,    ///< textures
  L,    ///< lighting
  B,    ///< the view back behind the cue ball
  O,    ///< the view from overhead (top-down) on/off
  F1,   ///< the help overlay on/off
  R,    ///< rematch (game over)
  N,    ///< a new game at a free table (game over)
  F11,  ///< full screen on/off
  Q,    ///< concede the rack (asks first)
  Y,    ///< yes (to the question asked); on a practice table with none asked, the last shot again
  I,    ///< the instant replay of the last shot
  Escape,
  // A practice table's keys (the window's requests).
  U,          ///< undo the last change
  J,          ///< the last shot sent (or loaded) from the table as it is
  H,          ///< ask the bot what it would play
  Num8,       ///< re-rack 8-ball
  Num9,       ///< re-rack 9-ball
  Num0,       ///< re-rack 10-ball
  Backspace,  ///< clear the table (the cue ball alone)
  F5,         ///< save the table and the last shot as a scenario file
  F6,         ///< load a scenario file
  F7,         ///< the physics pane on/off
  Tab,        ///< every pane hidden / shown again
  Minus,      ///< power down a step (0.05 m/s; with Shift 0.5)
  Equal,      ///< power up a step (the '=' / '+' key)
  Enter,      ///< shoot at the power set
  // The rules' choice (the Your choice pane's numbers).
  Num1,  ///< the first choice offered
  Num2,  ///< the second
  Num3,  ///< the third
  Num4,  ///< the fourth
};

/// The index of the choice a number key picks (Num1: 0 ... Num4: 3); none for other keys.
std::optional<int> choiceIndexOf(Key key);

/// Modifier keys held with a key.
struct Mods {
  bool shift = false;
  bool ctrl = false;
  bool alt = false;  ///< fine: the aim turns in small steps
};

enum class MouseButton : std::uint8_t { Left, Right };

/// The key of a name as scripts spell it ("LEFT", "SPACE", "A", ...), case-insensitive.
std::optional<Key> keyFromName(std::string_view name);

}  // namespace pool::app
