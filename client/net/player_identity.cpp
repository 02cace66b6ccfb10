// Key and seat files per player name.
#include "client/net/player_identity.h"

#include <cstdio>
#include <cstdlib>
#include <system_error>

namespace pool::client {
namespace {

/// Letters, digits, '-' and '_' as they are; every other byte as %XX (names are UTF-8).
std::string fileNameOf(const std::string& name) {
  std::string out;
  for (const char ch : name) {
    const auto byte = static_cast<unsigned char>(ch);
    const bool plain = (byte >= 'a' && byte <= 'z') || (byte >= 'A' && byte <= 'Z') ||
                       (byte >= '0' && byte <= '9') || byte == '-' || byte == '_';
    if (plain) {
      out += ch;
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", byte);
      out += hex;
    }
  }
  return out;
}

}  // namespace

std::filesystem::path defaultIdentityDir() {
  if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && *config) {
    return std::filesystem::path(config) / "pool" / "players";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".config" / "pool" / "players";
  }
  return {};
}

PlayerIdentity::PlayerIdentity(std::filesystem::path dir, const std::string& name)
    : base_(std::move(dir) / fileNameOf(name)) {}

Result<protocol::KeyPair> PlayerIdentity::key() const {
  std::error_code ignored;
  std::filesystem::create_directories(base_.parent_path(), ignored);
  std::filesystem::permissions(base_.parent_path(), std::filesystem::perms::owner_all, ignored);
  return protocol::loadOrCreateKeyFile(base_.string() + ".key");
}

std::optional<SeatRecord> PlayerIdentity::seat() const {
  auto read = readSeatFile(base_.string() + ".seat");
  return read ? *read : std::nullopt;
}

std::string PlayerIdentity::keepSeat(const SeatRecord& record) const {
  return writeSeatFile(base_.string() + ".seat", record);
}

void PlayerIdentity::forgetSeat() const {
  std::error_code ignored;
  std::filesystem::remove(base_.string() + ".seat", ignored);
}

}  // namespace pool::client
