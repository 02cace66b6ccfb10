// Script parsing and frame-by-frame playback.
#include "client/app/input_script.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace pool::app {
namespace {

/// Reads "shift", "ctrl" and "alt" into `mods`; false on any other word (named in `bad`).
bool readMods(const std::vector<std::string>& words, Mods& mods, std::string& bad) {
  for (const std::string& mod : words) {
    if (mod == "shift") {
      mods.shift = true;
    } else if (mod == "ctrl") {
      mods.ctrl = true;
    } else if (mod == "alt") {
      mods.alt = true;
    } else {
      bad = mod;
      return false;
    }
  }
  return true;
}

Result<ScriptStep> parseLine(std::istringstream& words, const std::string& verb) {
  using R = Result<ScriptStep>;
  ScriptStep step;
  if (verb == "down" || verb == "up") {
    std::string name;
    words >> name;
    const auto key = keyFromName(name);
    if (!key) return R::fail("unknown key '" + name + "'");
    step.kind = verb == "down" ? ScriptStep::Kind::Down : ScriptStep::Kind::Up;
    step.key = *key;
    std::vector<std::string> mods;
    for (std::string mod; words >> mod;) mods.push_back(mod);
    std::string bad;
    if (!readMods(mods, step.mods, bad)) return R::fail("unknown modifier '" + bad + "'");
    return R::ok(step);
  }
  if (verb == "frames") {
    step.kind = ScriptStep::Kind::Frames;
    if (!(words >> step.count) || step.count < 0) return R::fail("frames needs a count >= 0");
    return R::ok(step);
  }
  if (verb == "wait") {
    std::string what;
    words >> what;
    if (what == "aiming") {
      step.kind = ScriptStep::Kind::WaitAiming;
      return R::ok(step);
    }
    if (what == "live" || what == "rest") {
      step.kind = what == "live" ? ScriptStep::Kind::WaitLive : ScriptStep::Kind::WaitRest;
      return R::ok(step);
    }
    if (what == "over" || what == "table") {
      step.kind = what == "over" ? ScriptStep::Kind::WaitOver : ScriptStep::Kind::WaitTable;
      return R::ok(step);
    }
    if (what == "shot" && (words >> step.count) && step.count >= 0) {
      step.kind = ScriptStep::Kind::WaitShot;
      return R::ok(step);
    }
    return R::fail("wait needs 'aiming', 'shot N', 'over', 'table', 'live' or 'rest'");
  }
  if (verb == "mouse") {
    std::string what;
    words >> what;
    std::vector<std::string> args;
    for (std::string w; words >> w;) args.push_back(w);
    if (what == "press" && args == std::vector<std::string>{"cue"}) {
      step.kind = ScriptStep::Kind::MouseOnCue;
      return R::ok(step);
    }
    if (what == "release" && args.empty()) {
      step.kind = ScriptStep::Kind::MouseRelease;
      step.count = 1;  // released where the mouse is
      return R::ok(step);
    }
    if (what == "press") {
      step.kind = ScriptStep::Kind::MousePress;
    } else if (what == "move") {
      step.kind = ScriptStep::Kind::MouseMove;
    } else if (what == "release") {
      step.kind = ScriptStep::Kind::MouseRelease;
    } else if (what == "by") {
      step.kind = ScriptStep::Kind::MouseBy;
    } else {
      return R::fail("mouse needs 'press', 'move', 'release' or 'by'");
    }
    std::istringstream numbers(args.size() >= 2 ? args[0] + " " + args[1] : std::string());
    if (!(numbers >> step.x >> step.y) || !std::isfinite(step.x) || !std::isfinite(step.y)) {
      return R::fail("mouse " + what + " needs X Y in pixels");
    }
    // A press may hold modifiers (Ctrl: a stroke; Alt: fine aim); no other step takes them.
    const std::vector<std::string> mods(args.begin() + 2, args.end());
    std::string bad;
    if (!mods.empty() && step.kind != ScriptStep::Kind::MousePress) {
      return R::fail("mouse " + what + " takes no modifiers");
    }
    if (!readMods(mods, step.mods, bad)) return R::fail("unknown modifier '" + bad + "'");
    return R::ok(step);
  }
  if (verb == "capture") {
    step.kind = ScriptStep::Kind::Capture;
    if (!(words >> step.path)) return R::fail("capture needs a file");
    return R::ok(step);
  }
  if (verb == "quit") {
    step.kind = ScriptStep::Kind::Quit;
    return R::ok(step);
  }
  return R::fail("unknown step '" + verb + "'");
}

}  // namespace

Result<std::vector<ScriptStep>> parseScript(const std::string& text) {
  using R = Result<std::vector<ScriptStep>>;
  std::vector<ScriptStep> steps;
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string verb;
    if (!(words >> verb)) continue;
    auto step = parseLine(words, verb);
    if (!step) return R::fail("line " + std::to_string(number) + ": " + step.error());
    steps.push_back(*step);
  }
  return R::ok(std::move(steps));
}

Result<std::vector<ScriptStep>> loadScript(const std::string& path) {
  std::ifstream in(path);
  if (!in) return Result<std::vector<ScriptStep>>::fail("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  auto steps = parseScript(text.str());
  if (!steps) return Result<std::vector<ScriptStep>>::fail(path + ": " + steps.error());
  return steps;
}

std::vector<ScriptStep> ScriptPlayer::frame(const ScriptConditions& now) {
  std::vector<ScriptStep> due;
  if (frames_left_ > 0) {
    --frames_left_;
    return due;
  }
  while (next_ < steps_.size()) {
    const ScriptStep& step = steps_[next_];
    const bool wait =
        step.kind == ScriptStep::Kind::WaitAiming || step.kind == ScriptStep::Kind::WaitShot ||
        step.kind == ScriptStep::Kind::WaitOver || step.kind == ScriptStep::Kind::WaitTable ||
        step.kind == ScriptStep::Kind::WaitLive || step.kind == ScriptStep::Kind::WaitRest;
    // `now` was seen before this frame's steps: a wait after one is judged on the next frame.
    if (wait && !due.empty()) return due;
    const bool waiting = (step.kind == ScriptStep::Kind::WaitAiming && !now.can_aim) ||
                         (step.kind == ScriptStep::Kind::WaitOver && !now.over) ||
                         (step.kind == ScriptStep::Kind::WaitTable && !now.at_table) ||
                         (step.kind == ScriptStep::Kind::WaitLive && now.replaying) ||
                         (step.kind == ScriptStep::Kind::WaitRest && now.moving) ||
                         (step.kind == ScriptStep::Kind::WaitShot &&
                          now.shot_number < static_cast<std::uint32_t>(step.count));
    if (waiting) return due;
    ++next_;
    if (wait) continue;
    if (step.kind == ScriptStep::Kind::Frames) {
      frames_left_ = step.count;
      if (frames_left_ > 0) {
        --frames_left_;
        return due;
      }
      continue;
    }
    due.push_back(step);
    if (step.kind == ScriptStep::Kind::Quit) return due;
  }
  return due;
}

}  // namespace pool::app
