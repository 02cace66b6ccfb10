// Identifiers as the HUD says them: rule, foul, choice, pocket and placement names (snake_case on
// the wire and in logs) turned into words, so no underscore ever reaches the screen.
#pragma once

#include <string>
#include <string_view>

namespace pool::app {

/// The words for one identifier: a phrase where plain words would read badly
/// ("behind_head_string" → "behind the head string", "eight_on_foul" → "the 8 pocketed on a
/// foul"), otherwise its underscores as spaces ("foot_right_corner" → "foot right corner").
std::string spoken(std::string_view identifier);

/// `text` with every word that contains an underscore (letters, digits, underscores) spoken; the
/// rest unchanged.
std::string spokenText(std::string_view text);

}  // namespace pool::app
