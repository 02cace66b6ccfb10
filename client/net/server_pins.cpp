// Pinned server keys and their file.
#include "client/net/server_pins.h"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <system_error>

#include "client/net/player_identity.h"
#include "protocol/server_signature.h"

namespace pool::client {

namespace {

std::string hexOf(std::span<const std::uint8_t> bytes) {
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  for (const auto b : bytes) {
    out += kHex[b >> 4];
    out += kHex[b & 15];
  }
  return out;
}

bool keyFromHex(const std::string& hex, std::array<std::uint8_t, protocol::kPublicKeyBytes>& key) {
  if (hex.size() != key.size() * 2) return false;
  for (std::size_t i = 0; i < key.size(); ++i) {
    int value = 0;
    for (std::size_t k = 0; k < 2; ++k) {
      const char c = hex[2 * i + k];
      const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
      if (digit < 0) return false;
      value = value * 16 + digit;
    }
    key[i] = static_cast<std::uint8_t>(value);
  }
  return true;
}

void ownerOnly(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::permissions(
      path, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write, ec);
}

}  // namespace

std::filesystem::path defaultServerPinFile() {
  const auto players = defaultIdentityDir();
  return players.empty() ? players : players.parent_path() / "servers";
}

ServerPins::ServerPins(std::filesystem::path file) : file_(std::move(file)) {
  if (!file_.empty()) load();
}

void ServerPins::load() {
  std::error_code ec;
  if (!std::filesystem::exists(file_, ec)) return;
  std::ifstream in(file_);
  if (!in) {
    file_problem_ = "cannot read " + file_.string();
    return;
  }
  std::string line;
  while (std::getline(in, line) && pins_.size() < kMaxPins) {
    std::istringstream words(line);
    std::string server, hex;
    std::array<std::uint8_t, protocol::kPublicKeyBytes> key{};
    if (words >> server >> hex && protocol::validServerId(server) && keyFromHex(hex, key)) {
      pins_[server] = key;
    }
  }
}

void ServerPins::append(const std::string& server, std::span<const std::uint8_t> key) {
  if (file_.empty()) return;
  std::error_code ec;
  if (!file_.parent_path().empty()) std::filesystem::create_directories(file_.parent_path(), ec);
  const bool fresh = !std::filesystem::exists(file_, ec);
  {
    std::ofstream out(file_, std::ios::app);
    out << server << ' ' << hexOf(key) << '\n';
    if (!out) file_problem_ = "cannot write " + file_.string();
  }
  if (fresh) ownerOnly(file_);
}

void ServerPins::rewrite() {
  if (file_.empty()) return;
  const auto temporary = std::filesystem::path(file_.string() + ".tmp");
  {
    std::ofstream out(temporary, std::ios::trunc);
    for (const auto& [server, key] : pins_) out << server << ' ' << hexOf(key) << '\n';
    if (!out) {
      file_problem_ = "cannot write " + temporary.string();
      return;
    }
  }
  ownerOnly(temporary);
  std::error_code ec;
  std::filesystem::rename(temporary, file_, ec);
  if (ec) file_problem_ = "cannot rename to " + file_.string() + ": " + ec.message();
}

PinCheck ServerPins::check(const std::string& server, std::span<const std::uint8_t> key) {
  if (!protocol::validServerId(server) || key.size() != protocol::kPublicKeyBytes) {
    return PinCheck::Refused;
  }
  ++checks_;
  const auto it = pins_.find(server);
  if (it != pins_.end()) {
    return std::equal(key.begin(), key.end(), it->second.begin()) ? PinCheck::Same
                                                                  : PinCheck::Changed;
  }
  const auto waiting = probation_.find(server);
  if (waiting != probation_.end()) {
    if (!std::equal(key.begin(), key.end(), waiting->second.key.begin())) return PinCheck::Changed;
    if (!settle(server)) {
      probation_order_.erase({waiting->second.last, server});
      waiting->second.last = checks_;
      probation_order_.emplace(checks_, server);
    }
    return PinCheck::Same;
  }
  if (pins_.size() < kMaxPins) {
    auto& pin = pins_[server];
    std::copy(key.begin(), key.end(), pin.begin());
    append(server, key);
    return PinCheck::FirstSight;
  }
  if (probation_.size() >= kMaxProbation) {
    const auto oldest = probation_order_.begin();
    probation_.erase(oldest->second);
    probation_order_.erase(oldest);
    ++evicted_;
  }
  auto& pin = probation_[server];
  std::copy(key.begin(), key.end(), pin.key.begin());
  pin.last = checks_;
  probation_order_.emplace(checks_, server);
  return PinCheck::FirstSight;
}

bool ServerPins::settle(const std::string& server) {
  const auto it = probation_.find(server);
  if (it == probation_.end() || pins_.size() >= kMaxPins) return false;
  pins_[server] = it->second.key;
  append(server, it->second.key);
  probation_order_.erase({it->second.last, server});
  probation_.erase(it);
  return true;
}

const std::array<std::uint8_t, protocol::kPublicKeyBytes>* ServerPins::pinned(
    const std::string& server) const {
  const auto it = pins_.find(server);
  if (it != pins_.end()) return &it->second;
  const auto waiting = probation_.find(server);
  return waiting == probation_.end() ? nullptr : &waiting->second.key;
}

bool ServerPins::onProbation(const std::string& server) const {
  return probation_.count(server) != 0;
}

bool ServerPins::forget(const std::string& server) {
  const auto waiting = probation_.find(server);
  if (waiting != probation_.end()) {
    probation_order_.erase({waiting->second.last, server});
    probation_.erase(waiting);
    return true;
  }
  if (pins_.erase(server) == 0) return false;
  rewrite();
  return true;
}

}  // namespace pool::client
