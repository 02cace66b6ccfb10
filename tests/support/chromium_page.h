// Headless Chromium driven over its DevTools protocol on a pipe (--remote-debugging-pipe: JSON
// messages ending in NUL, written to its fd 3 and read from its fd 4): open a page, evaluate
// JavaScript, set the viewport, take screenshots. For the web page's tests.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace pool::client::test {

/// The Chromium Debian installs, or empty when there is none.
inline std::string chromiumPath() {
  for (const char* p : {"/usr/bin/chromium", "/usr/bin/chromium-browser"}) {
    if (::access(p, X_OK) == 0) return p;
  }
  return {};
}

/// Standard base64 (as CDP sends screenshots) to bytes; stops at '=' or anything not base64.
inline std::string base64Decode(const std::string& in) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  std::uint32_t bits = 0;
  int count = 0;
  for (char c : in) {
    const int v = value(c);
    if (v < 0) break;
    bits = (bits << 6) | static_cast<std::uint32_t>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<char>((bits >> count) & 0xff));
    }
  }
  return out;
}

/// One headless Chromium with one page. Started by the constructor (check started()), killed by
/// the destructor. Calls wait for their answer up to a deadline and return nullopt past it.
class ChromiumPage {
 public:
  ChromiumPage(const std::string& user_data_dir, int width, int height) {
    const std::string chromium = chromiumPath();
    if (chromium.empty()) return;
    int to_browser[2], from_browser[2];
    if (::pipe(to_browser) != 0 || ::pipe(from_browser) != 0) return;
    pid_ = ::fork();
    if (pid_ == 0) {
      ::setpgid(0, 0);
      // The browser reads commands on fd 3 and writes answers on fd 4.
      ::dup2(to_browser[0], 3);
      ::dup2(from_browser[1], 4);
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      for (int fd = 5; fd < 1024; ++fd) ::close(fd);
      const std::string size =
          "--window-size=" + std::to_string(width) + "," + std::to_string(height);
      const std::string data = "--user-data-dir=" + user_data_dir;
      std::vector<std::string> args{chromium,
                                    "--headless",
                                    "--no-sandbox",
                                    "--disable-gpu",
                                    "--disable-quic",
                                    "--no-first-run",
                                    "--disable-background-networking",
                                    "--disable-component-update",
                                    "--disable-sync",
                                    "--enable-unsafe-swiftshader",
                                    "--use-angle=swiftshader",
                                    "--remote-debugging-pipe",
                                    data,
                                    size,
                                    "about:blank"};
      std::vector<char*> argv;
      for (auto& a : args) argv.push_back(a.data());
      argv.push_back(nullptr);
      ::execv(chromium.c_str(), argv.data());
      ::_exit(127);
    }
    ::close(to_browser[0]);
    ::close(from_browser[1]);
    out_ = to_browser[1];
    in_ = from_browser[0];
    ::fcntl(in_, F_SETFL, O_NONBLOCK);
    ::signal(SIGPIPE, SIG_IGN);
  }

  ~ChromiumPage() {
    if (out_ >= 0) ::close(out_);
    if (in_ >= 0) ::close(in_);
    if (pid_ > 0) {
      ::kill(-pid_, SIGKILL);
      ::kill(pid_, SIGKILL);
      int status = 0;
      ::waitpid(pid_, &status, 0);
    }
  }
  ChromiumPage(const ChromiumPage&) = delete;
  ChromiumPage& operator=(const ChromiumPage&) = delete;

  bool started() const { return pid_ > 0 && out_ >= 0; }

  /// Opens `url` in a new tab and attaches to it; false when the browser did not answer.
  bool open(const std::string& url, std::chrono::milliseconds timeout) {
    const auto target = call("Target.createTarget", {{"url", "about:blank"}}, timeout, false);
    if (!target) return false;
    const auto attached =
        call("Target.attachToTarget", {{"targetId", (*target)["targetId"]}, {"flatten", true}},
             timeout, false);
    if (!attached) return false;
    session_ = (*attached)["sessionId"].get<std::string>();
    return call("Page.enable", nlohmann::json::object(), timeout) &&
           call("Page.navigate", {{"url", url}}, timeout);
  }

  /// The viewport in CSS pixels (after open()) at one device pixel per CSS pixel (`mobile`: a
  /// phone's).
  bool setViewport(int width, int height, bool mobile, std::chrono::milliseconds timeout) {
    return call(
               "Emulation.setDeviceMetricsOverride",
               {{"width", width}, {"height", height}, {"deviceScaleFactor", 1}, {"mobile", mobile}},
               timeout)
        .has_value();
  }

  /// The value of a JavaScript expression (returned by value), or nullopt on a timeout or an
  /// exception (see lastError()).
  std::optional<nlohmann::json> evaluate(const std::string& expression,
                                         std::chrono::milliseconds timeout) {
    const auto result = call(
        "Runtime.evaluate",
        {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}}, timeout);
    if (!result) return std::nullopt;
    if (result->contains("exceptionDetails")) {
      error_ = (*result)["exceptionDetails"].dump();
      return std::nullopt;
    }
    const auto& value = (*result)["result"];
    return value.contains("value") ? value["value"] : nlohmann::json();
  }

  /// The page as a PNG file's bytes, or empty.
  std::string screenshot(std::chrono::milliseconds timeout) {
    const auto result = call("Page.captureScreenshot", {{"format", "png"}}, timeout);
    if (!result || !result->contains("data")) return {};
    return base64Decode((*result)["data"].get<std::string>());
  }

  const std::string& lastError() const { return error_; }

  /// Sends one command and waits for its answer's result.
  std::optional<nlohmann::json> call(const std::string& method, const nlohmann::json& params,
                                     std::chrono::milliseconds timeout, bool in_session = true) {
    nlohmann::json message{{"id", ++next_id_}, {"method", method}, {"params", params}};
    if (in_session && !session_.empty()) message["sessionId"] = session_;
    std::string text = message.dump();
    text.push_back('\0');
    std::size_t sent = 0;
    while (sent < text.size()) {
      const ssize_t n = ::write(out_, text.data() + sent, text.size() - sent);
      if (n <= 0) {
        error_ = "cannot write to the browser";
        return std::nullopt;
      }
      sent += static_cast<std::size_t>(n);
    }
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
      for (std::size_t end; (end = buffer_.find('\0')) != std::string::npos;) {
        const auto answer = nlohmann::json::parse(buffer_.substr(0, end), nullptr, false);
        buffer_.erase(0, end + 1);
        if (answer.is_discarded() || !answer.contains("id") || answer["id"] != next_id_) continue;
        if (answer.contains("error")) {
          error_ = method + ": " + answer["error"].dump();
          return std::nullopt;
        }
        return answer.value("result", nlohmann::json::object());
      }
      pollfd p{in_, POLLIN, 0};
      ::poll(&p, 1, 100);
      char chunk[65536];
      for (ssize_t n; (n = ::read(in_, chunk, sizeof chunk)) > 0;) buffer_.append(chunk, n);
    }
    error_ = method + ": no answer in time";
    return std::nullopt;
  }

 private:
  pid_t pid_ = -1;
  int out_ = -1;
  int in_ = -1;
  std::string session_;
  std::string buffer_;
  std::int64_t next_id_ = 0;
  std::string error_;
};

}  // namespace pool::client::test
