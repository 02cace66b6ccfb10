// Key names for input scripts.
#include "client/app/input.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <utility>

namespace pool::app {

std::optional<Key> keyFromName(std::string_view name) {
  static constexpr std::array<std::pair<std::string_view, Key>, 40> kNames{{
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
      {"ENTER", Key::Enter},
  }};
  std::string upper(name);
  std::transform(upper.begin(), upper.end(), upper.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  for (const auto& [text, key] : kNames) {
    if (text == upper) return key;
  }
  return std::nullopt;
}

}  // namespace pool::app
