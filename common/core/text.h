// Text from the outside world: names checked as UTF-8 without control characters, and any text
// made safe to write into a log line.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace pool {

/// True when `text` is 1 to `max_bytes` bytes of well-formed UTF-8 (no overlong forms, no
/// surrogates, nothing above U+10FFFF) without control characters (U+0000–U+001F, U+007F,
/// U+0080–U+009F).
bool isCleanUtf8(std::string_view text, std::size_t max_bytes);

/// `text` for a log line: printable UTF-8 as it is, every control character, backslash and byte
/// that is not well-formed UTF-8 as `\xNN`, so that nobody can forge a line or a terminal escape.
std::string escapedForLog(std::string_view text);

}  // namespace pool
