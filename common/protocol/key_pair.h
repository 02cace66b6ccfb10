// A player's Ed25519 key pair (libsodium): made once, kept in a file, used to sign shot commands.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "core/result.h"

namespace pool::protocol {

inline constexpr std::size_t kPublicKeyBytes = 32;  ///< Ed25519 public key
inline constexpr std::size_t kSecretKeyBytes = 64;  ///< libsodium's secret key (seed + public)
inline constexpr std::size_t kSignatureBytes = 64;  ///< Ed25519 detached signature

/// One key pair. The secret half never leaves the process except into its key file.
struct KeyPair {
  std::array<std::uint8_t, kPublicKeyBytes> public_key{};
  std::array<std::uint8_t, kSecretKeyBytes> secret_key{};

  /// The public key as a JoinRequest carries it.
  std::vector<std::uint8_t> publicKey() const { return {public_key.begin(), public_key.end()}; }
};

/// A fresh random key pair.
KeyPair generateKeyPair();

/// The key pair of a libsodium secret key (64 bytes: seed and public half); an error naming
/// `where` for any other length.
Result<KeyPair> keyPairFromSecret(std::span<const std::uint8_t> secret, const std::string& where);

/// The key pair kept in `path` (the secret key in hex, one line). A missing file is created with
/// a fresh pair, readable by its owner only; a file that exists but does not hold a key is an
/// error (and is left as it is).
Result<KeyPair> loadOrCreateKeyFile(const std::filesystem::path& path);

}  // namespace pool::protocol
