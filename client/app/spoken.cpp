// Phrases for the identifiers that plain words would not explain.
#include "client/app/spoken.h"

#include <array>
#include <cctype>
#include <utility>

namespace pool::app {

namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 19> kPhrases{{
    {"behind_head_string", "behind the head string"},
    {"behind_head_string_direct", "a ball behind the head string struck directly"},
    {"not_behind_head_string", "not behind the head string"},
    {"play_on", "play on"},
    {"ball_in_hand", "take ball in hand"},
    {"respot_eight", "respot the 8"},
    {"re_break", "break again"},
    {"opponent_re_breaks", "the opponent breaks again"},
    {"eight_pocketed", "the 8 pocketed"},
    {"eight_on_foul", "the 8 pocketed on a foul"},
    {"eight_before_group_cleared", "the 8 pocketed before the group was cleared"},
    {"eight_with_last_group_ball", "the 8 pocketed with the group's last ball"},
    {"eight_wrong_pocket", "the 8 in a pocket not called"},
    {"eight_off_table", "the 8 off the table"},
    {"no_cushion_after_contact", "no cushion after the contact"},
    {"no_ball_in_hand", "no ball in hand"},
    {"off_slate", "off the slate"},
    {"over_pocket", "over a pocket"},
    {"not_finite", "not a number"},
}};

bool wordChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

}  // namespace

std::string spoken(std::string_view identifier) {
  for (const auto& [id, phrase] : kPhrases) {
    if (id == identifier) return std::string(phrase);
  }
  std::string out(identifier);
  for (char& c : out) {
    if (c == '_') c = ' ';
  }
  return out;
}

std::string spokenText(std::string_view text) {
  std::string out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (!wordChar(text[i])) {
      out += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && wordChar(text[end])) ++end;
    const std::string_view word = text.substr(i, end - i);
    out += word.find('_') == std::string_view::npos ? std::string(word) : spoken(word);
    i = end;
  }
  return out;
}

}  // namespace pool::app
