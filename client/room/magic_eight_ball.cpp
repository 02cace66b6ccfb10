// The answers and the pick: FNV-1a over the normalised question, mixed with the seed (splitmix64).
#include "client/room/magic_eight_ball.h"

#include <cctype>

#include "core/split_mix64.h"

namespace pool::room {

namespace {

/// Lower case, runs of whitespace as one space, no leading or trailing space.
std::string normalise(std::string_view question) {
  std::string out;
  bool space = false;
  for (const char c : question) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isspace(u)) {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += static_cast<char>(std::tolower(u));
  }
  return out;
}

std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

}  // namespace

const std::array<std::string_view, 20>& classicAnswers() {
  static constexpr std::array<std::string_view, 20> kAnswers{
      "It is certain.",
      "It is decidedly so.",
      "Without a doubt.",
      "Yes definitely.",
      "You may rely on it.",
      "As I see it, yes.",
      "Most likely.",
      "Outlook good.",
      "Yes.",
      "Signs point to yes.",
      "Reply hazy, try again.",
      "Ask again later.",
      "Better not tell you now.",
      "Cannot predict now.",
      "Concentrate and ask again.",
      "Don't count on it.",
      "My reply is no.",
      "My sources say no.",
      "Outlook not so good.",
      "Very doubtful.",
  };
  return kAnswers;
}

AnswerKind answerKind(std::size_t index) {
  if (index < 10) return AnswerKind::Affirmative;
  if (index < 15) return AnswerKind::NonCommittal;
  return AnswerKind::Negative;
}

Result<std::string> answer(std::string_view question, std::uint64_t seed) {
  const std::string q = normalise(question);
  bool meaningful = false;
  for (const char c : q) meaningful = meaningful || std::isalnum(static_cast<unsigned char>(c));
  if (!meaningful) return Result<std::string>::fail("ask the Magic Eight Ball a question first");
  const std::uint64_t pick = splitMix64(fnv1a(q) ^ splitMix64(seed));
  return Result<std::string>::ok(std::string(classicAnswers()[pick % classicAnswers().size()]));
}

}  // namespace pool::room
