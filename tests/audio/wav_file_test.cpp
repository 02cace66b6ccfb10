// The WAV writer: a standard 16-bit mono PCM header, the samples back within quantisation.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "client/audio/wav_file.h"

namespace pool::audio {
namespace {

std::uint32_t le(const std::string& b, std::size_t at, int bytes) {
  std::uint32_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[at + i]);
  return v;
}

TEST(WavFile, WritesAHeaderAndSamplesAnyReaderUnderstands) {
  const std::string path = ::testing::TempDir() + "pool_audio_test.wav";
  const std::vector<float> samples = {0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 2.0f, -2.0f};
  auto written = writeWav(path, samples, 44100);
  ASSERT_TRUE(written) << written.error();
  std::ifstream in(path, std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(b.size(), 44 + 2 * samples.size());
  EXPECT_EQ(*written, b.size());
  EXPECT_EQ(b.substr(0, 4), "RIFF");
  EXPECT_EQ(le(b, 4, 4), b.size() - 8);
  EXPECT_EQ(b.substr(8, 8), "WAVEfmt ");
  EXPECT_EQ(le(b, 20, 2), 1u);  // PCM
  EXPECT_EQ(le(b, 22, 2), 1u);  // mono
  EXPECT_EQ(le(b, 24, 4), 44100u);
  EXPECT_EQ(le(b, 28, 4), 88200u);
  EXPECT_EQ(le(b, 34, 2), 16u);
  EXPECT_EQ(b.substr(36, 4), "data");
  EXPECT_EQ(le(b, 40, 4), 2 * samples.size());
  const auto sample = [&](int i) {
    return static_cast<std::int16_t>(le(b, 44 + 2 * static_cast<std::size_t>(i), 2));
  };
  EXPECT_EQ(sample(0), 0);
  EXPECT_EQ(sample(1), 16384);  // 0.5 · 32767 rounded
  EXPECT_EQ(sample(2), -16384);
  EXPECT_EQ(sample(3), 32767);
  EXPECT_EQ(sample(4), -32767);
  EXPECT_EQ(sample(5), 32767);  // clamped
  EXPECT_EQ(sample(6), -32767);
  std::remove(path.c_str());
}

TEST(WavFile, AnUnwritablePathFailsWithOneLine) {
  auto written = writeWav("/no/such/dir/out.wav", std::vector<float>(10, 0.0f), 48000);
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error(), "/no/such/dir/out.wav: cannot open for writing");
}

}  // namespace
}  // namespace pool::audio
