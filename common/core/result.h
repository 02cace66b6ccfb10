// Result<T>: a value or a one-line reason, for expected failures (bad input, missing files).
#pragma once

#include <optional>
#include <string>
#include <utility>

namespace pool {

/// A value of T, or the reason there is none. Expected failures return this; asserts are for
/// broken invariants only.
template <class T>
class Result {
 public:
  static Result ok(T value) {
    Result r;
    r.value_ = std::move(value);
    return r;
  }
  static Result fail(std::string reason) {
    Result r;
    r.error_ = std::move(reason);
    return r;
  }

  explicit operator bool() const { return value_.has_value(); }
  bool hasValue() const { return value_.has_value(); }
  T& operator*() { return *value_; }
  const T& operator*() const { return *value_; }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }
  T& value() { return *value_; }
  const T& value() const { return *value_; }
  /// The reason for the failure; empty on success.
  const std::string& error() const { return error_; }

 private:
  Result() = default;
  std::optional<T> value_;
  std::string error_;
};

}  // namespace pool
