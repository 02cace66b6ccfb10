// A GameClient for tests that keeps everything it handed out and every line it logged.
#pragma once

#include <chrono>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "client/net/game_client.h"

namespace pool::client::test {

using namespace std::chrono_literals;

/// A GameClient that keeps everything poll() handed out and every line it logged.
struct Watcher {
  explicit Watcher(std::uint32_t domain, std::filesystem::path pins = {})
      : client({domain, "", "watcher", std::move(pins),
                [this](const std::string& line, bool) { lines.push_back(line); }}) {}

  /// Polls until `done()` or `timeout`; returns done().
  bool pumpUntil(const std::function<bool()>& done, std::chrono::milliseconds timeout = 30s) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      for (auto& e : client.poll()) events.push_back(std::move(e));
      if (done()) return true;
      if (std::chrono::steady_clock::now() >= deadline) return false;
      client.wait(20ms);
    }
  }

  bool logged(const std::string& part) const {
    for (const auto& l : lines) {
      if (l.find(part) != std::string::npos) return true;
    }
    return false;
  }

  template <class T, class F>
  bool handedOut(F&& matches) const {
    for (const auto& e : events) {
      if (const auto* v = std::get_if<T>(&e); v && matches(*v)) return true;
    }
    return false;
  }

  std::vector<std::string> lines;
  std::vector<ClientEvent> events;
  GameClient client;
};

}  // namespace pool::client::test
