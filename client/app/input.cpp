// Key names for input scripts, and the choice a number key picks.
#include "client/app/input.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <utility>

namespace pool::app {

std::optional<Key> keyFromName(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, Key>, 44> kNames{{
      {"LEFT", Key::Left},   {"RIGHT", Key::Right},   {"UP", Key::Up},
      {"DOWN", Key::Down},   {"SPACE", Key::Space},   {"A", Key::A},
      {"Z", Key::Z},         {"S", Key::S},           {"X", Key::X},
      {"G", Key::G},         {"V", Key::V},           {"C", Key::C},
      {"K", Key::K},         {"P", Key::P},           {"T", Key::T},
      {"L", Key::L},         {"B", Key::B},           {"O", Key::O},
      {"F1", Key::F1},       {"R", Key::R},           {"N", Key::N},
      {"F11", Key::F11},     {"ESCAPE", Key::Escape}, {"Q", Key::Q},
      {"I", Key::I},         {"U", Key::U},           {"Y", Key::Y},
      {"J", Key::J},         {"H", Key::H},           {"8", Key::Num8},
      {"9", Key::Num9},      {"0", Key::Num0},        {"BACKSPACE", Key::Backspace},
      {"F5", Key::F5},       {"F6", Key::F6},         {"F7", Key::F7},
      {"TAB", Key::Tab},     {"MINUS", Key::Minus},   {"EQUAL", Key::Equal},
      {"ENTER", Key::Enter}, {"1", Key::Num1},        {"2", Key::Num2},
      {"3", Key::Num3},      {"4", Key::Num4},
  }};
  std::string upper(name);
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  for (const auto& [text, key] : kNames) {
    if (text == upper) return key;
  }
  return std::nullopt;
}

std::optional<int> choiceIndexOf(Key key) {
  switch (key) {
    case Key::Num1:
      return 0;
    case Key::Num2:
      return 1;
    case Key::Num3:
      return 2;
    case Key::Num4:
      return 3;
    default:
      return std::nullopt;
  }
}

}  // namespace pool::app
