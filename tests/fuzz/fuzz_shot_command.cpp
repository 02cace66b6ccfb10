// libFuzzer target: validateShotCommand on a ShotCommand whose every field comes from the input.
#include <fuzzer/FuzzedDataProvider.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "net/sample.h"
#include "net/shot_command_check.h"
#include "net/wire_fields.h"
#include "shot_command_verdict.h"

namespace {

/// Any double, NaN, infinities, subnormals and huge values included: its 64 bits from the input.
double anyDouble(FuzzedDataProvider& in) {
  return std::bit_cast<double>(in.ConsumeIntegral<std::uint64_t>());
}

/// A bounded IDL string filled with any bytes, terminated or not.
template <std::size_t N>
void anyText(FuzzedDataProvider& in, char (&dst)[N]) {
  const std::vector<char> bytes =
      in.ConsumeBytes<char>(in.ConsumeIntegralInRange<std::size_t>(0, N));
  std::memset(dst, 0, N);
  if (!bytes.empty()) std::memcpy(dst, bytes.data(), bytes.size());
}

/// The signature sequence: real bytes of any length, or a length that lies (no buffer behind it).
void anySignature(FuzzedDataProvider& in, pool_ShotCommand& c) {
  if (in.ConsumeBool()) {
    const auto bytes =
        in.ConsumeBytes<std::uint8_t>(in.ConsumeIntegralInRange<std::size_t>(0, 200));
    const auto span =
        pool::net::resizeSequence(c.signature, static_cast<std::uint32_t>(bytes.size()));
    if (!bytes.empty()) std::memcpy(span.data(), bytes.data(), bytes.size());
  } else {
    c.signature._length = in.ConsumeIntegral<std::uint32_t>();
    c.signature._maximum = c.signature._length;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  pool::net::Sample<pool_ShotCommand> sample;
  pool_ShotCommand& c = *sample;
  anyText(in, c.match);
  c.seat = in.ConsumeIntegral<std::int16_t>();
  c.seat_token = in.ConsumeIntegral<std::uint64_t>();
  c.seq = in.ConsumeIntegral<std::uint32_t>();
  c.yaw = anyDouble(in);
  c.tip_side = anyDouble(in);
  c.tip_height = anyDouble(in);
  c.elevation = anyDouble(in);
  c.speed = anyDouble(in);
  c.speed_is_ball = in.ConsumeBool();
  c.called_ball = in.ConsumeIntegral<std::int16_t>();
  anyText(in, c.called_pocket);
  c.safety = in.ConsumeBool();
  c.has_cue_ball_placement = in.ConsumeBool();
  c.cue_ball_x = anyDouble(in);
  c.cue_ball_y = anyDouble(in);
  pool::net::setRawValue(c.option, in.ConsumeIntegral<std::int32_t>());
  anySignature(in, c);

  const pool::net::CommandCheck check = pool::net::validateShotCommand(c);
  pool::fuzz::checkVerdict(c, check);
  if (c.signature._buffer == nullptr) c.signature = {};  // a lying length owns nothing to free
  return 0;
}
