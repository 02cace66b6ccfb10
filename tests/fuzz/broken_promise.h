// How a fuzz target reports a broken promise: a line on stderr, then abort (libFuzzer keeps the
// input).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace pool::fuzz {

[[noreturn]] inline void brokenPromise(const std::string& what) {
  std::fprintf(stderr, "broken promise: %s\n", what.c_str());
  std::abort();
}

/// A refusal's reason is one non-empty line.
inline void expectOneLineReason(const std::string& why) {
  if (why.empty() || why.find('\n') != std::string::npos) {
    brokenPromise("refusal is not one line: '" + why + "'");
  }
}

}  // namespace pool::fuzz
