// The admin request's JSON form and its checks.
#include "server/admin/admin_request.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <set>

#include "core/check.h"
#include "core/hex.h"
#include "core/text.h"

namespace pool::admin {

namespace {

using Json = nlohmann::json;

struct VerbInfo {
  Verb verb;
  const char* name;
  std::set<std::string> fields;         ///< besides "verb"; every one required
  std::set<std::string> optional = {};  ///< may be left out (a yes or no, false when out)
};

const std::array<VerbInfo, 11>& verbs() {
  static const std::array<VerbInfo, 11> kVerbs{{
      {Verb::Status, "status", {}},
      {Verb::List, "list", {}},
      {Verb::Close, "close", {"match", "reason"}},
      {Verb::Ban, "ban", {"key", "reason"}},
      {Verb::Unban, "unban", {"key"}},
      {Verb::Bans, "bans", {}},
      {Verb::Backup, "backup", {"path"}},
      {Verb::TournamentCreate,
       "tournament-create",
       {"name", "format", "game", "race", "entrants"},
       {"handicap"}},
      {Verb::TournamentStart, "tournament-start", {"tournament"}},
      {Verb::TournamentCancel, "tournament-cancel", {"tournament"}},
      {Verb::Tournaments, "tournaments", {}},
  }};
  return kVerbs;
}

constexpr std::size_t kMaxMatchId = 39;
constexpr std::size_t kMaxReason = 120;
constexpr std::size_t kKeyBytes = 32;
constexpr std::size_t kMaxPath = 4095;
// A tournament's name is held like a player's (match_registry: 1-31 bytes of clean UTF-8).
constexpr std::size_t kMaxTournamentName = 31;
constexpr std::int64_t kMaxRace = 15;
// pool_tournament's field (tournament/entrant.h: kMinEntrants, kMaxEntrants); pool_admin links
// nothing of it, so the bounds are written here.
constexpr std::int64_t kMinEntrants = 3;
constexpr std::int64_t kMaxEntrants = 32;
// The games' numbers (rules::gameNumber: 8-, 9- and 10-ball, three-cushion, snooker); pool_admin
// links nothing of the rules, so they are written here.
constexpr std::array<std::int64_t, 5> kGameNumbers{8, 9, 10, 3, 22};
constexpr std::array<const char*, 3> kFormats{"single", "double", "round-robin"};

Result<AdminRequest> refuse(std::string why) {
  return Result<AdminRequest>::fail(std::move(why));
}

bool printable(const std::string& text) {
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) return false;
  }
  return true;
}

/// The string field `name` of `doc`; a reason when it is not a string.
Result<std::string> text(const Json& doc, const char* name) {
  const Json& v = doc.at(name);
  if (!v.is_string()) return Result<std::string>::fail(std::string(name) + ": must be a string");
  return Result<std::string>::ok(v.get<std::string>());
}

/// The whole-number field `name` of `doc` (one above int64's range reads as int64's largest); a
/// reason when it is not a whole number.
Result<std::int64_t> wholeNumber(const Json& doc, const char* name) {
  const Json& v = doc.at(name);
  if (!v.is_number_integer()) {
    return Result<std::int64_t>::fail(std::string(name) + ": must be a whole number");
  }
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    constexpr auto kTop = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
    return Result<std::int64_t>::ok(static_cast<std::int64_t>(std::min(u, kTop)));
  }
  return Result<std::int64_t>::ok(v.get<std::int64_t>());
}

bool isNumberField(const std::string& field) {
  return field == "game" || field == "race" || field == "entrants";
}

/// The verbs' names, for the refusal of an unknown one: "status, list, ...".
std::string verbNames() {
  std::string out;
  for (const auto& v : verbs()) out += (out.empty() ? "" : ", ") + std::string(v.name);
  return out;
}

/// Checks the whole-number field `field` of a request into `out`.
Check<> readNumber(const std::string& field, std::int64_t n, AdminRequest& out) {
  if (field == "game") {
    if (std::find(kGameNumbers.begin(), kGameNumbers.end(), n) == kGameNumbers.end()) {
      return Check<>::refuse("game",
                             "game: " + std::to_string(n) + " is not a game (8, 9, 10, 3 or 22)");
    }
    out.game = static_cast<int>(n);
  } else if (field == "race") {
    if (n < 1 || n > kMaxRace) return Check<>::refuse("race", "race: 1-15 racks");
    out.race = static_cast<int>(n);
  } else if (field == "entrants") {
    if (n < kMinEntrants || n > kMaxEntrants) {
      return Check<>::refuse("entrants", "entrants: 3-32");
    }
    out.entrants = static_cast<int>(n);
  }
  return Check<>::pass();
}

}  // namespace

const char* toString(Verb verb) {
  for (const auto& v : verbs()) {
    if (v.verb == verb) return v.name;
  }
  return "unknown";
}

Result<AdminRequest> parseRequest(const std::string& line) {
  if (line.size() > kMaxRequestBytes) return refuse("request longer than 8192 bytes");
  const Json doc = Json::parse(line, nullptr, false);
  if (doc.is_discarded() || !doc.is_object()) return refuse("not a JSON object");
  if (!doc.contains("verb") || !doc["verb"].is_string()) return refuse("verb: missing");
  const std::string name = doc["verb"].get<std::string>();
  const VerbInfo* info = nullptr;
  for (const auto& v : verbs()) {
    if (name == v.name) info = &v;
  }
  if (!info) {
    return refuse("verb: '" + escapedForLog(name) + "' is not one of " + verbNames());
  }
  for (const auto& [field, value] : doc.items()) {
    if (field != "verb" && !info->fields.count(field) && !info->optional.count(field)) {
      return refuse(escapedForLog(field) + ": not a field of " + name);
    }
  }
  AdminRequest out;
  out.verb = info->verb;
  for (const auto& field : info->optional) {
    if (!doc.contains(field)) continue;
    if (!doc[field].is_boolean()) return refuse(field + ": must be true or false");
    if (field == "handicap") out.handicap = doc[field].get<bool>();
  }
  for (const auto& field : info->fields) {
    if (!doc.contains(field)) return refuse(field + ": missing (" + name + " needs it)");
    if (isNumberField(field)) {
      auto number = wholeNumber(doc, field.c_str());
      if (!number) return refuse(number.error());
      if (auto ok = readNumber(field, *number, out); !ok) return refuse(ok.error());
      continue;
    }
    auto value = text(doc, field.c_str());
    if (!value) return refuse(value.error());
    std::string& v = *value;
    if (field == "match") {
      if (v.empty() || v.size() > kMaxMatchId || !printable(v)) {
        return refuse("match: 1-39 printable bytes");
      }
      out.match = v;
    } else if (field == "reason") {
      if (v.empty() || !isCleanUtf8(v, kMaxReason)) {
        return refuse("reason: 1-120 bytes of UTF-8 without control characters");
      }
      out.reason = v;
    } else if (field == "key") {
      auto bytes = bytesFromHex(v);
      if (!bytes || bytes->size() != kKeyBytes) {
        return refuse("key: an Ed25519 public key is 64 hex digits");
      }
      out.key = std::move(*bytes);
    } else if (field == "path") {
      if (v.empty() || v.size() > kMaxPath || v.front() != '/' || !printable(v)) {
        return refuse("path: an absolute path without control characters");
      }
      out.path = v;
    } else if (field == "tournament") {
      if (v.empty() || v.size() > kMaxMatchId || !printable(v)) {
        return refuse("tournament: 1-39 printable bytes");
      }
      out.tournament = v;
    } else if (field == "name") {
      if (v.empty() || !isCleanUtf8(v, kMaxTournamentName)) {
        return refuse("name: 1-31 bytes of UTF-8 without control characters");
      }
      out.name = v;
    } else if (field == "format") {
      if (std::find(kFormats.begin(), kFormats.end(), v) == kFormats.end()) {
        return refuse("format: '" + escapedForLog(v) +
                      "' is not one of single, double, round-robin");
      }
      out.format = v;
    }
  }
  return Result<AdminRequest>::ok(std::move(out));
}

std::string requestLine(const AdminRequest& r) {
  Json doc{{"verb", toString(r.verb)}};
  switch (r.verb) {
    case Verb::Close:
      doc["match"] = r.match;
      doc["reason"] = r.reason;
      break;
    case Verb::Ban:
      doc["key"] = hexOf(r.key);
      doc["reason"] = r.reason;
      break;
    case Verb::Unban:
      doc["key"] = hexOf(r.key);
      break;
    case Verb::Backup:
      doc["path"] = r.path;
      break;
    case Verb::TournamentCreate:
      doc["name"] = r.name;
      doc["format"] = r.format;
      doc["game"] = r.game;
      doc["race"] = r.race;
      doc["entrants"] = r.entrants;
      if (r.handicap) doc["handicap"] = true;
      break;
    case Verb::TournamentStart:
    case Verb::TournamentCancel:
      doc["tournament"] = r.tournament;
      break;
    default:
      break;
  }
  return doc.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace pool::admin
