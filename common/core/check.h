// Check<Code>: a pass, or a refusal with its reason code and one sentence for a person.
#pragma once

#include <string>
#include <utility>

namespace pool {

/// What a check answers. `Code` is the reason a program branches on (an enum of the module, or a
/// snake_case name); the sentence is "<what>: <why>", for a log line or an error message.
/// Converts to true when the check passed.
template <class Code = std::string>
class [[nodiscard]] Check {
 public:
  static Check pass() { return Check(); }
  static Check refuse(Code code, std::string sentence) {
    Check c;
    c.refused_ = true;
    c.code_ = std::move(code);
    c.sentence_ = std::move(sentence);
    return c;
  }

  explicit operator bool() const { return !refused_; }
  bool ok() const { return !refused_; }
  /// The reason; a default Code when the check passed.
  const Code& code() const { return code_; }
  /// The sentence; empty when the check passed.
  const std::string& error() const { return sentence_; }

 private:
  Check() = default;
  bool refused_ = false;
  Code code_{};
  std::string sentence_;
};

}  // namespace pool
