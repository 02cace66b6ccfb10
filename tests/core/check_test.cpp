// Check<Code> and Result<T>: a pass carries no reason; a refusal carries its code and sentence.
#include "core/check.h"
#include "core/result.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace pool {
namespace {

enum class Why : std::uint8_t { None, TooLong, Empty };

Check<Why> nameCheck(const std::string& name) {
  if (name.empty()) return Check<Why>::refuse(Why::Empty, "name: empty");
  if (name.size() > 8) return Check<Why>::refuse(Why::TooLong, "name: at most 8 characters");
  return Check<Why>::pass();
}

TEST(Check, APassIsTrueAndCarriesNoReason) {
  const auto ok = nameCheck("eight");
  EXPECT_TRUE(ok);
  EXPECT_TRUE(ok.ok());
  EXPECT_EQ(ok.code(), Why::None);
  EXPECT_EQ(ok.error(), "");
}

TEST(Check, ARefusalCarriesItsCodeAndSentence) {
  const auto empty = nameCheck("");
  EXPECT_FALSE(empty);
  EXPECT_EQ(empty.code(), Why::Empty);
  EXPECT_EQ(empty.error(), "name: empty");
  const auto long_name = nameCheck("a name too long");
  EXPECT_FALSE(long_name.ok());
  EXPECT_EQ(long_name.code(), Why::TooLong);
  EXPECT_EQ(long_name.error(), "name: at most 8 characters");
}

TEST(Check, StringCodesByDefault) {
  const auto no = Check<>::refuse("bad_race", "race: must be 1 to 15 racks");
  EXPECT_FALSE(no);
  EXPECT_EQ(no.code(), "bad_race");
  EXPECT_TRUE(Check<>::pass());
}

TEST(Result, AFailureCarriesACodeAndASentence) {
  const auto coded = Result<int>::fail("bad_race", "race: must be 1 to 15 racks");
  EXPECT_FALSE(coded);
  EXPECT_EQ(coded.code(), "bad_race");
  EXPECT_EQ(coded.error(), "race: must be 1 to 15 racks");
  const auto plain = Result<int>::fail("cannot read the file");
  EXPECT_EQ(plain.code(), "failed");
  const auto value = Result<int>::ok(8);
  EXPECT_TRUE(value);
  EXPECT_EQ(value.code(), "");
}

}  // namespace
}  // namespace pool
