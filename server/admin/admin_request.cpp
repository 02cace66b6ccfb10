// The admin request's JSON form and its checks.
#include "server/admin/admin_request.h"

#include <nlohmann/json.hpp>

#include <array>
#include <set>

#include "core/hex.h"
#include "core/text.h"

namespace pool::admin {

namespace {

using Json = nlohmann::json;

struct VerbInfo {
  Verb verb;
  const char* name;
  std::set<std::string> fields;  ///< besides "verb"; every one required
};

const std::array<VerbInfo, 7>& verbs() {
  static const std::array<VerbInfo, 7> kVerbs{{
      {Verb::Status, "status", {}},
      {Verb::List, "list", {}},
      {Verb::Close, "close", {"match", "reason"}},
      {Verb::Ban, "ban", {"key", "reason"}},
      {Verb::Unban, "unban", {"key"}},
      {Verb::Bans, "bans", {}},
      {Verb::Backup, "backup", {"path"}},
  }};
  return kVerbs;
}

constexpr std::size_t kMaxMatchId = 39;
constexpr std::size_t kMaxReason = 120;
constexpr std::size_t kKeyBytes = 32;
constexpr std::size_t kMaxPath = 4095;

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
    return refuse("verb: '" + escapedForLog(name) +
                  "' is not one of status, list, close, ban, unban, bans, backup");
  }
  for (const auto& [field, value] : doc.items()) {
    if (field != "verb" && !info->fields.count(field)) {
      return refuse(escapedForLog(field) + ": not a field of " + name);
    }
  }
  AdminRequest out;
  out.verb = info->verb;
  for (const auto& field : info->fields) {
    if (!doc.contains(field)) return refuse(field + ": missing (" + name + " needs it)");
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
    default:
      break;
  }
  return doc.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace pool::admin
