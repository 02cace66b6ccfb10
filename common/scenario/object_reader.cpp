// Typed reading of one JSON object's members with one-line errors naming the field.
#include "scenario/object_reader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>

#include "core/text.h"

namespace pool::scenario {

using nlohmann::json;

namespace {

// Shortest text that reads back as the same double.
std::string shortest(double x) {
  std::array<char, 32> buf{};
  const auto end = std::to_chars(buf.data(), buf.data() + buf.size(), x).ptr;
  return std::string(buf.data(), end);
}

}  // namespace

std::string Interval::text() const {
  // Appended piece by piece: `"(" + std::string` trips g++ 12's -Wrestrict false positive at -O3.
  std::string out = lo_open ? "(" : "[";
  out += shortest(lo);
  out += ", ";
  out += shortest(hi);
  out += ']';
  return out;
}

ObjectReader::ObjectReader(const json& value, std::string path)
    : value_(value), path_(std::move(path)) {
  if (!value_.is_object()) {
    error_ = (path_.empty() ? std::string("scenario") : path_) + ": must be a JSON object, got " +
             value_.type_name();
  }
}

std::string ObjectReader::fieldPath(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void ObjectReader::fail(std::string_view key, std::string_view reason) {
  // Keys come from the file: escaped, so a refusal stays one line whatever they hold.
  if (error_.empty()) error_ = fieldPath(escapedForLog(key)) + ": " + std::string(reason);
}

void ObjectReader::onlyKnown(std::initializer_list<std::string_view> known) {
  if (!ok()) return;
  for (const auto& item : value_.items()) {
    if (std::find(known.begin(), known.end(), item.key()) != known.end()) continue;
    std::string list;
    for (std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
    fail(item.key(), "unknown field (expected one of " + list + ")");
    return;
  }
}

const json* ObjectReader::find(std::string_view key, Presence presence) {
  if (!ok()) return nullptr;
  const auto it = value_.find(key);
  if (it != value_.end()) return &*it;
  if (presence == Presence::Required) fail(key, "missing (required)");
  return nullptr;
}

bool ObjectReader::expect(std::string_view key, const json& value, bool good,
                          std::string_view what) {
  if (!good) fail(key, "must be " + std::string(what) + ", got " + shortDump(value));
  return good;
}

void ObjectReader::number(std::string_view key, double& out, Presence presence) {
  const json* v = find(key, presence);
  if (v == nullptr || !expect(key, *v, v->is_number(), "a number")) return;
  const double d = v->get<double>();
  if (expect(key, *v, std::isfinite(d), "a finite number")) out = d;
}

void ObjectReader::numberIn(std::string_view key, const Interval& range, double& out,
                            Presence presence) {
  const json* v = find(key, presence);
  if (v == nullptr) return;
  const std::string what = "a finite number in " + range.text();
  if (!expect(key, *v, v->is_number(), what)) return;
  const double d = v->get<double>();
  if (expect(key, *v, std::isfinite(d) && range.contains(d), what)) out = d;
}

void ObjectReader::integer(std::string_view key, std::int64_t lo, std::int64_t hi, int& out,
                           Presence presence) {
  const json* v = find(key, presence);
  if (v == nullptr) return;
  const std::string what = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!expect(key, *v, v->is_number_integer(), what)) return;
  const bool in_range =
      v->is_number_unsigned()
          ? v->get<std::uint64_t>() <= static_cast<std::uint64_t>(std::max<std::int64_t>(hi, 0))
          : v->get<std::int64_t>() >= lo && v->get<std::int64_t>() <= hi;
  if (expect(key, *v, in_range, what)) out = static_cast<int>(v->get<std::int64_t>());
}

void ObjectReader::unsignedInteger(std::string_view key, std::uint64_t& out) {
  const json* v = find(key, Presence::Optional);
  if (v != nullptr && expect(key, *v, v->is_number_unsigned(), "an integer in [0, 2^64 - 1]")) {
    out = v->get<std::uint64_t>();
  }
}

void ObjectReader::string(std::string_view key, std::string& out, Presence presence) {
  const json* v = find(key, presence);
  if (v != nullptr && expect(key, *v, v->is_string(), "a string")) out = v->get<std::string>();
}

const json* ObjectReader::member(std::string_view key, Presence presence) {
  return find(key, presence);
}

std::string shortDump(const json& value) {
  constexpr std::size_t kMax = 40;
  std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > kMax) text = text.substr(0, kMax - 3) + "...";
  return text;
}

std::string indexPath(std::string_view path, std::size_t index) {
  return std::string(path) + "[" + std::to_string(index) + "]";
}

}  // namespace pool::scenario
