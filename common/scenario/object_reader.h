// Typed reading of a JSON object's members, keeping the first one-line error ("<path>: <why>").
#pragma once

#include "core/check.h"

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace pool::scenario {

/// Whether a member must be present.
enum class Presence { Optional, Required };

/// A closed interval, or one open at its lower end: "(0, 12]", "[0, 1000]".
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  bool lo_open = false;
  bool contains(double x) const { return (lo_open ? x > lo : x >= lo) && x <= hi; }
  std::string text() const;
};

/// Reads the members of one JSON object. Each read leaves `out` untouched when the member is
/// absent and optional; the first failure is kept and later reads do nothing.
class ObjectReader {
 public:
  /// `path` names the object in messages ("shot", "balls[2]"; "" for the top level).
  ObjectReader(const nlohmann::json& value, std::string path);

  /// Fails on any member not in `known` ("<path>.<key>: unknown field (expected one of ...)").
  void onlyKnown(std::initializer_list<std::string_view> known);

  /// A finite JSON number.
  void number(std::string_view key, double& out, Presence presence = Presence::Optional);
  /// A finite number inside `range`.
  void numberIn(std::string_view key, const Interval& range, double& out,
                Presence presence = Presence::Optional);
  /// A JSON integer in [lo, hi].
  void integer(std::string_view key, std::int64_t lo, std::int64_t hi, int& out,
               Presence presence = Presence::Optional);
  /// A non-negative JSON integer (full 64-bit range).
  void unsignedInteger(std::string_view key, std::uint64_t& out);
  /// A JSON string.
  void string(std::string_view key, std::string& out, Presence presence = Presence::Optional);
  /// The member itself, or nullptr when absent (a failure when required).
  const nlohmann::json* member(std::string_view key, Presence presence = Presence::Optional);

  /// Records a failure for a member unless one is already recorded.
  void fail(std::string_view key, std::string_view reason);
  /// "<path>.<key>" (or "<key>" at the top level).
  std::string fieldPath(std::string_view key) const;

  bool ok() const { return error_.empty(); }
  /// The first failure, "" if none.
  const std::string& error() const { return error_; }
  /// The reading as a check: passed, or refused with the first error ("bad_field").
  Check<> check() const { return ok() ? Check<>::pass() : Check<>::refuse("bad_field", error_); }

 private:
  const nlohmann::json* find(std::string_view key, Presence presence);
  bool expect(std::string_view key, const nlohmann::json& value, bool good, std::string_view what);

  const nlohmann::json& value_;
  std::string path_;
  std::string error_;
};

/// A value as JSON text, shortened to 40 characters, for messages.
std::string shortDump(const nlohmann::json& value);

/// "<path>[<index>]".
std::string indexPath(std::string_view path, std::size_t index);

}  // namespace pool::scenario
