// Scripted input for tests and demos (pool-client --script FILE): timed key presses that drive
// the same controls as the keyboard, frame by frame.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "client/app/input.h"
#include "core/result.h"

namespace pool::app {

/// One line of a script.
struct ScriptStep {
  enum class Kind : std::uint8_t {
    Down,          ///< press `key` with `mods`
    Up,            ///< release `key`
    Frames,        ///< let `count` frames pass
    WaitAiming,    ///< wait until this screen may aim
    WaitShot,      ///< wait until the match's shot number reaches `count`
    WaitOver,      ///< wait until the match followed is over
    WaitTable,     ///< wait until this screen holds a seat in a match that is not over
    WaitLive,      ///< wait until no instant replay is showing (the live table is drawn)
    WaitRest,      ///< wait until no shot's motion is being drawn
    Quit,          ///< close the client
    MousePress,    ///< press the left button at (`x`, `y`) (pixels from the top-left corner)
    MouseMove,     ///< move the mouse to (`x`, `y`)
    MouseRelease,  ///< release the left button at (`x`, `y`)
    MouseOnCue,    ///< move the mouse onto the cue ball as drawn and press the left button there
    MouseBy,       ///< move the mouse by (`x`, `y`) pixels
    Capture,       ///< write this frame, as drawn, to the PNG file `path`
  };
  Kind kind = Kind::Frames;
  Key key = Key::Space;
  Mods mods;
  int count = 0;
  double x = 0.0;
  double y = 0.0;
  std::string path;  ///< Capture's file
};

/// Parses a script: one step a line, '#' starts a comment.
///   down KEY [shift] [ctrl] [alt] | up KEY | frames N | wait aiming | wait shot N | wait over |
///   wait table | wait live | wait rest | quit | mouse press X Y [shift] [ctrl] [alt] | mouse move
///   X Y | mouse by DX DY | mouse release [X Y] | mouse press cue | capture FILE
/// KEY as keyFromName spells it. The first bad line fails the whole script, with its number.
Result<std::vector<ScriptStep>> parseScript(const std::string& text);

/// Reads and parses a script file.
Result<std::vector<ScriptStep>> loadScript(const std::string& path);

/// What the `wait` steps wait for, as the client sees it this frame.
struct ScriptConditions {
  bool can_aim = false;
  std::uint32_t shot_number = 0;  ///< of the match followed
  bool over = false;              ///< the match followed is over
  bool at_table = false;          ///< seated in a match that is not over
  bool replaying = false;         ///< the instant replay is showing
  bool moving = false;            ///< a shot's motion is being drawn
};

/// Plays a script: each frame, the steps due now.
class ScriptPlayer {
 public:
  explicit ScriptPlayer(std::vector<ScriptStep> steps) : steps_(std::move(steps)) {}

  /// The steps to apply this frame (key presses and releases, or a Quit), the waits judged on
  /// `now` (as seen before this frame's steps: a wait that follows a step of this frame is
  /// judged on the next one).
  std::vector<ScriptStep> frame(const ScriptConditions& now);
  bool done() const { return next_ >= steps_.size() && frames_left_ == 0; }

 private:
  std::vector<ScriptStep> steps_;
  std::size_t next_ = 0;
  int frames_left_ = 0;
};

}  // namespace pool::app
