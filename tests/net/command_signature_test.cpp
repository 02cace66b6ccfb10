// The signed bytes of a shot command cover every field that matters, and only the signer's key
// verifies them; key files keep a key pair across processes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "net/messages.h"
#include "protocol/command_signature.h"
#include "protocol/key_pair.h"

namespace pool::net {
namespace {

using namespace protocol;

ShotRequest sample() {
  ShotRequest r;
  r.match = "srv-3";
  r.seat = 1;
  r.seat_token = 0x0123456789abcdefULL;
  r.seq = 17;
  r.cue = {0.5, 0.1, -0.2, 0.05, 3.5, false};
  r.called_ball = 9;
  r.called_pocket = "foot_left_corner";
  r.cue_ball_at = Eigen::Vector2d(-0.8, 0.2);
  r.option = ShotOption::BallInHand;
  return r;
}

TEST(CommandSignature, TheEncodingIsTheEnvelopeWithTagShotAndAFixedLayout) {
  const std::vector<std::uint8_t> bytes = signedBytes(sample());
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 8), "POOL-MSG");
  EXPECT_EQ(bytes[8], kEnvelopeLayoutVersion);  // little-endian u32
  EXPECT_EQ(bytes[12], kProtocolVersion);
  EXPECT_EQ(bytes[16], static_cast<std::uint8_t>(MessageTag::Shot));
  EXPECT_EQ(bytes[17], 5);  // the match id's length, then its bytes
  EXPECT_EQ(std::string(bytes.begin() + 18, bytes.begin() + 23), "srv-3");
  EXPECT_EQ(bytes[58], 1);     // seat, i32 after the 40-byte match field
  EXPECT_EQ(bytes[62], 0xef);  // the token's low byte
  EXPECT_EQ(bytes[70], 17);    // seq
  EXPECT_EQ(bytes.size(), kSignedCommandBytes);
  // An empty command encodes to the same size: nothing depends on the text lengths.
  EXPECT_EQ(signedBytes(ShotRequest{}).size(), bytes.size());
}

TEST(CommandSignature, EveryFieldThatMattersChangesTheBytes) {
  const std::vector<std::uint8_t> base = signedBytes(sample());
  const std::vector<std::pair<const char*, std::function<void(ShotRequest&)>>> changes = {
      {"match", [](ShotRequest& r) { r.match = "srv-4"; }},
      {"seat", [](ShotRequest& r) { r.seat = 0; }},
      {"token", [](ShotRequest& r) { r.seat_token ^= 1; }},
      {"seq", [](ShotRequest& r) { r.seq = 18; }},
      {"yaw", [](ShotRequest& r) { r.cue.yaw = 0.5000001; }},
      {"tip_side", [](ShotRequest& r) { r.cue.tip_side = 0.0; }},
      {"tip_height", [](ShotRequest& r) { r.cue.tip_height = 0.2; }},
      {"elevation", [](ShotRequest& r) { r.cue.elevation = 0.0; }},
      {"speed", [](ShotRequest& r) { r.cue.speed = 11.0; }},
      {"speed_is_ball", [](ShotRequest& r) { r.cue.speed_is_ball = true; }},
      {"called_ball", [](ShotRequest& r) { r.called_ball = 10; }},
      {"no call", [](ShotRequest& r) { r.called_ball.reset(); }},
      {"called_pocket", [](ShotRequest& r) { r.called_pocket = "foot_right_corner"; }},
      {"safety", [](ShotRequest& r) { r.safety = true; }},
      {"placement x", [](ShotRequest& r) { r.cue_ball_at->x() = -0.7; }},
      {"no placement", [](ShotRequest& r) { r.cue_ball_at.reset(); }},
      {"option", [](ShotRequest& r) { r.option = ShotOption::PlayOn; }},
  };
  for (const auto& [name, change] : changes) {
    ShotRequest r = sample();
    change(r);
    EXPECT_NE(signedBytes(r), base) << name;
  }
  ShotRequest signed_one = sample();
  signed_one.signature.assign(64, 0xab);  // the signature is not part of what it signs
  EXPECT_EQ(signedBytes(signed_one), base);
}

TEST(CommandSignature, OnlyTheSignersKeyVerifiesAndOnlyTheSignedFields) {
  const KeyPair mine = generateKeyPair();
  const KeyPair theirs = generateKeyPair();
  EXPECT_NE(mine.public_key, theirs.public_key);
  ShotRequest r = sample();
  EXPECT_EQ(verifyCommand(r, mine.publicKey()), SignatureCheck::Unsigned);
  signCommand(r, mine);
  ASSERT_EQ(r.signature.size(), kSignatureBytes);
  EXPECT_EQ(verifyCommand(r, mine.publicKey()), SignatureCheck::Valid);
  EXPECT_EQ(verifyCommand(r, theirs.publicKey()), SignatureCheck::BadSignature);
  EXPECT_EQ(verifyCommand(r, {}), SignatureCheck::BadSignature);
  ShotRequest tampered = r;
  tampered.cue.speed = 12.0;
  EXPECT_EQ(verifyCommand(tampered, mine.publicKey()), SignatureCheck::BadSignature);
  ShotRequest short_signature = r;
  short_signature.signature.pop_back();
  EXPECT_EQ(verifyCommand(short_signature, mine.publicKey()), SignatureCheck::BadSignature);
  ShotRequest flipped = r;
  flipped.signature[0] ^= 0x80;
  EXPECT_EQ(verifyCommand(flipped, mine.publicKey()), SignatureCheck::BadSignature);
}

class KeyFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("pool-key-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(KeyFile, IsCreatedOnceOwnerOnlyAndReadBackTheSame) {
  const auto path = dir_ / "bot.key";
  const auto made = loadOrCreateKeyFile(path);
  ASSERT_TRUE(made) << made.error();
  const auto perms = std::filesystem::status(path).permissions();
  EXPECT_EQ(perms & (std::filesystem::perms::group_all | std::filesystem::perms::others_all),
            std::filesystem::perms::none);
  const auto again = loadOrCreateKeyFile(path);
  ASSERT_TRUE(again) << again.error();
  EXPECT_EQ(again->public_key, made->public_key);
  EXPECT_EQ(again->secret_key, made->secret_key);
  // The key read back signs what the first one verifies.
  ShotRequest r = sample();
  signCommand(r, *again);
  EXPECT_EQ(verifyCommand(r, made->publicKey()), SignatureCheck::Valid);
}

TEST_F(KeyFile, ABrokenFileIsAnErrorAndIsLeftAsItIs) {
  const auto path = dir_ / "broken.key";
  std::ofstream(path) << "not a key\n";
  const auto read = loadOrCreateKeyFile(path);
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().find("broken.key"), std::string::npos) << read.error();
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "not a key");
}

}  // namespace
}  // namespace pool::net
