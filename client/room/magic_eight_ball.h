// The Magic Eight Ball: its twenty classic answers and a pure, seeded pick of one for a question.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/result.h"

namespace pool::room {

/// What an answer leans to: ten say yes, five are non-committal, five say no.
enum class AnswerKind { Affirmative, NonCommittal, Negative };

/// The twenty answers, affirmative first, then non-committal, then negative.
const std::array<std::string_view, 20>& classicAnswers();

/// The kind of answer `index` (0–19) in classicAnswers().
AnswerKind answerKind(std::size_t index);

/// The answer to `question` for `seed`: the same question (ignoring case and spacing) and seed
/// always get the same answer; different seeds spread over all twenty. Fails, with a one-line
/// reason, on a question with no letters or digits.
Result<std::string> answer(std::string_view question, std::uint64_t seed);

}  // namespace pool::room
