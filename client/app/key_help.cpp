// The help overlay's list of keys.
#include "client/app/key_help.h"

namespace pool::app {

const std::vector<KeyHelp>& keyHelp() {
  static const std::vector<KeyHelp> kHelp{
      {"aiming", "Left / Right, left drag", "turn the cue (a press: 0.25 degrees)"},
      {"aiming", "Alt + Left / Right, Alt + drag", "fine aim (a press: 0.05 degrees)"},
      {"aiming", "Up / Down", "raise and lower the view"},
      {"aiming", "Shift + arrows", "move the view around the cue ball"},
      {"aiming", "Ctrl + arrows", "move the tip on the cue ball (spin)"},
      {"aiming", "A / Z", "raise / lower the cue (jump and masse)"},
      {"aiming", "hold Space, release", "charge the power, shoot (Esc cancels)"},
      {"aiming", "- / + (Shift: x10), Enter", "set the cue speed in 0.05 m/s steps / shoot at it"},
      {"aiming", "Ctrl + drag down, then up",
       "stroke the cue: it strikes at the mouse's speed (let go or Esc: no shot)"},
      {"aiming", "C / K", "call the next pocket / declare a safety"},
      {"snooker", "click a ball",
       "nominate it (a colour when on one, any ball with a free ball; again: drop it)"},
      {"ball in hand", "drag the cue ball", "place it where the rules allow"},
      {"a choice", "1 / 2 / 3 / 4",
       "answer the rules' choice (after a foul: play from here, a free ball, play again, the "
       "balls put back): the option of that number in the Your choice pane"},
      {"always", "B", "back behind the cue ball (watching: the whole table)"},
      {"always", "O", "the table from overhead, clear of the panes, on and off"},
      {"overhead", "S / X, wheel; right drag, Shift + arrows",
       "zoom; pan (O again: the whole table)"},
      {"watching", "arrows, left drag", "orbit the view, raise and lower it"},
      {"always", "right drag", "orbit the view"},
      {"always", "S / X, mouse wheel", "zoom in / out"},
      {"always", "G / V", "aim line and ghost ball / direction arrows"},
      {"always", "P / T / L", "wireframe / textures / lighting"},
      {"playing", "Q, then Y (Esc: no)", "concede the rack: the opponent wins it"},
      {"game over", "R / N", "rematch / a new game at a free table"},
      {"always", "I",
       "replay the last shot (the view turns and zooms as ever; a new shot ends it)"},
      {"practice", "drag any ball", "put it anywhere on the slate (the server checks the spot)"},
      {"practice", "U", "undo the last change (a shot, a layout, a rack)"},
      {"practice", "Y / J", "the last shot again from its table / from the table as it is"},
      {"practice", "H", "ask the bot what it would play (the cue turns to its aim)"},
      {"practice", "8 / 9 / 0, Backspace",
       "re-rack 8-, 9- or 10-ball (at a snooker or carom table: its own game) / clear the table"},
      {"practice", "F5 / F6", "save the table and the last shot as a scenario / load one"},
      {"practice", "F7", "the physics pane: this table's coefficients"},
      {"always", "F11", "full screen, on and off"},
      {"always", "Tab", "hide every pane (a question asked stays) / show them again"},
      {"always", "F1", "this help and the settings, on and off"},
  };
  return kHelp;
}

}  // namespace pool::app
