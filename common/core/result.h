// Result<T>: a value, or the reason there is none (a code and one sentence), for expected failures
// (bad input, missing files); a check with nothing to return answers with Check (core/check.h).
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
  /// A failure with a reason code a program can branch on ("bad_race") and its sentence.
  static Result fail(std::string code, std::string reason) {
    Result r = fail(std::move(reason));
    r.code_ = std::move(code);
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
  /// The failure's reason code; "failed" where none was given, empty on success.
  const std::string& code() const { return value_ || !code_.empty() ? code_ : kFailed; }

 private:
  Result() = default;
  inline static const std::string kFailed = "failed";
  std::optional<T> value_;
  std::string error_;
  std::string code_;
};

}  // namespace pool
