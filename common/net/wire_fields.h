// Helpers for the fields of generated wire types: bounded strings (char arrays) and sequences.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <type_traits>

#include "net/dds_detail.h"

namespace pool::net {

/// Copies `text` into a bounded IDL string (char[N], room for N-1 characters and the NUL).
/// Returns false when the text had to be cut to fit.
template <std::size_t N>
bool setText(char (&dst)[N], std::string_view text) {
  const std::size_t n = text.size() < N - 1 ? text.size() : N - 1;
  std::memcpy(dst, text.data(), n);
  std::memset(dst + n, 0, N - n);
  return n == text.size();
}

/// The text of a bounded IDL string, up to its NUL or its bound (safe on unterminated input).
template <std::size_t N>
std::string_view textOf(const char (&src)[N]) {
  const void* nul = std::memchr(src, 0, N);
  return {src, nul ? static_cast<std::size_t>(static_cast<const char*>(nul) - src) : N};
}

/// True when a bounded IDL string holds its NUL within its bound.
template <std::size_t N>
bool terminated(const char (&src)[N]) {
  return std::memchr(src, 0, N) != nullptr;
}

/// The integer held by an IDL enum field, read without assuming it is one of the enumerators (a
/// peer or a bug may have put any value there, and a C++ enum may not hold such a value).
template <class E>
std::int32_t rawValue(const E& field) {
  static_assert(std::is_enum_v<E> && sizeof(E) == sizeof(std::int32_t));
  std::int32_t value = 0;
  std::memcpy(&value, &field, sizeof value);
  return value;
}

/// Stores any integer in an IDL enum field (to build malformed samples in tests).
template <class E>
void setRawValue(E& field, std::int32_t value) {
  static_assert(std::is_enum_v<E> && sizeof(E) == sizeof(std::int32_t));
  std::memcpy(&field, &value, sizeof value);
}

/// The element type of a generated sequence type.
template <class Seq>
using ElementOf = std::remove_pointer_t<decltype(Seq::_buffer)>;

/// Gives a sequence `n` zeroed elements in a buffer the sequence owns (freed with its Sample), and
/// returns them. Any buffer it owned before is freed. Only for sequences of flat elements (every
/// sequence in pool.idl).
template <class Seq>
std::span<ElementOf<Seq>> resizeSequence(Seq& seq, std::uint32_t n) {
  using Element = ElementOf<Seq>;
  static_assert(std::is_trivially_copyable_v<Element>);
  if (seq._release && seq._buffer) {
    detail::freeBuffer(seq._buffer);
  }
  seq._buffer = n ? static_cast<Element*>(detail::allocZeroed(n * sizeof(Element))) : nullptr;
  seq._maximum = n;
  seq._length = n;
  seq._release = true;
  return {seq._buffer, n};
}

/// The elements of a sequence (empty when it has no buffer).
template <class Seq>
std::span<const ElementOf<Seq>> elementsOf(const Seq& seq) {
  if (!seq._buffer) {
    return {};
  }
  return {seq._buffer, seq._length};
}

/// Copies at most `bound` bytes of `bytes` into an octet sequence (empty input: empty sequence).
template <class Seq>
void setBytes(Seq& seq, std::span<const std::uint8_t> bytes, std::size_t bound) {
  const auto n = static_cast<std::uint32_t>(bytes.size() < bound ? bytes.size() : bound);
  auto out = resizeSequence(seq, n);
  if (n) std::memcpy(out.data(), bytes.data(), n);
}

}  // namespace pool::net
