// Ed25519 key pairs and their key files.
#include "protocol/key_pair.h"

#include <sodium.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "protocol/sodium_init.h"

namespace pool::protocol {

namespace {

std::string hexOf(const std::array<std::uint8_t, kSecretKeyBytes>& bytes) {
  std::string hex(bytes.size() * 2 + 1, '\0');
  sodium_bin2hex(hex.data(), hex.size(), bytes.data(), bytes.size());
  hex.pop_back();
  return hex;
}

Result<KeyPair> keyFromHex(const std::string& hex, const std::string& where) {
  KeyPair pair;
  std::size_t length = 0;
  if (sodium_hex2bin(pair.secret_key.data(), pair.secret_key.size(), hex.data(), hex.size(),
                     nullptr, &length, nullptr) != 0 ||
      length != kSecretKeyBytes) {
    return Result<KeyPair>::fail(where + ": not a key file (" +
                                 std::to_string(kSecretKeyBytes * 2) + " hex digits)");
  }
  return keyPairFromSecret(pair.secret_key, where);
}

}  // namespace

Result<KeyPair> keyPairFromSecret(std::span<const std::uint8_t> secret, const std::string& where) {
  if (secret.size() != kSecretKeyBytes) {
    return Result<KeyPair>::fail(where + ": not an Ed25519 secret key (" +
                                 std::to_string(secret.size()) + " bytes, not " +
                                 std::to_string(kSecretKeyBytes) + ")");
  }
  initSodium();
  KeyPair pair;
  std::copy(secret.begin(), secret.end(), pair.secret_key.begin());
  crypto_sign_ed25519_sk_to_pk(pair.public_key.data(), pair.secret_key.data());
  return Result<KeyPair>::ok(pair);
}

KeyPair generateKeyPair() {
  initSodium();
  KeyPair pair;
  crypto_sign_keypair(pair.public_key.data(), pair.secret_key.data());
  return pair;
}

Result<KeyPair> loadOrCreateKeyFile(const std::filesystem::path& path) {
  initSodium();
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    std::ifstream in(path);
    std::string hex;
    std::getline(in, hex);
    return keyFromHex(hex, path.string());
  }
  const KeyPair pair = generateKeyPair();
  const auto temporary = std::filesystem::path(path.string() + ".tmp");
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << hexOf(pair.secret_key) << "\n";
    if (!out) return Result<KeyPair>::fail("cannot write " + temporary.string());
  }
  std::filesystem::permissions(
      temporary, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write, ec);
  std::filesystem::rename(temporary, path, ec);
  if (ec) return Result<KeyPair>::fail("cannot rename to " + path.string() + ": " + ec.message());
  return Result<KeyPair>::ok(pair);
}

}  // namespace pool::protocol
