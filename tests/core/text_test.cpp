// Names from the network are well-formed UTF-8 without control characters; log lines escape
// whatever could forge a line or drive a terminal.
#include "core/text.h"

#include <gtest/gtest.h>

namespace pool {
namespace {

TEST(CleanUtf8, AcceptsNamesInAnyScriptAndCountsBytes) {
  EXPECT_TRUE(isCleanUtf8("Ada", 31));
  EXPECT_TRUE(isCleanUtf8("Zo\xC3\xAB", 31));                // Zoë: 2-byte sequence
  EXPECT_TRUE(isCleanUtf8("\xE6\x9D\x8E\xE5\x8D\x8E", 31));  // two CJK characters, 3 bytes each
  EXPECT_TRUE(isCleanUtf8("\xF0\x9F\x8E\xB1 8-ball", 31));   // U+1F3B1, 4 bytes
  EXPECT_TRUE(isCleanUtf8(std::string(31, 'a'), 31));
  EXPECT_FALSE(isCleanUtf8(std::string(32, 'a'), 31));
  EXPECT_FALSE(isCleanUtf8("", 31));
}

TEST(CleanUtf8, RefusesControlsAndMalformedSequences) {
  EXPECT_FALSE(isCleanUtf8("A\nda", 31));
  EXPECT_FALSE(isCleanUtf8("\x1B[2JAda", 31));        // ESC: a terminal escape
  EXPECT_FALSE(isCleanUtf8("Ada\x7F", 31));           // DEL
  EXPECT_FALSE(isCleanUtf8("Ada\xC2\x85", 31));       // U+0085 (NEL), a C1 control
  EXPECT_FALSE(isCleanUtf8("Zo\xEB", 31));            // Latin-1 ë: not UTF-8
  EXPECT_FALSE(isCleanUtf8("\xC0\xAF", 31));          // overlong '/'
  EXPECT_FALSE(isCleanUtf8("\xED\xA0\x80", 31));      // a surrogate
  EXPECT_FALSE(isCleanUtf8("\xF4\x90\x80\x80", 31));  // above U+10FFFF
  EXPECT_FALSE(isCleanUtf8("\xE6\x9D", 31));          // cut short
}

TEST(LogEscape, ControlsBackslashesAndBadBytesBecomeHex) {
  EXPECT_EQ(escapedForLog("Zo\xC3\xAB"), "Zo\xC3\xAB");
  EXPECT_EQ(escapedForLog("a\nb"), "a\\x0Ab");
  EXPECT_EQ(escapedForLog("\x1B[31m"), "\\x1B[31m");
  EXPECT_EQ(escapedForLog("x\\x0A"), "x\\x5Cx0A");  // a literal backslash cannot fake an escape
  EXPECT_EQ(escapedForLog("Zo\xEB"), "Zo\\xEB");
  EXPECT_EQ(escapedForLog(""), "");
}

}  // namespace
}  // namespace pool
