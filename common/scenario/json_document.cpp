// Strict JSON reading: follows the path of the value being parsed so every error names its field.
#include "scenario/json_document.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <set>
#include <vector>

namespace pool::scenario {
namespace {

using nlohmann::json;

// One open object or array while parsing.
struct Frame {
  bool is_array = false;
  std::size_t index = 0;       // arrays: the element being parsed
  std::string key;             // objects: the member being parsed
  std::set<std::string> keys;  // objects: members seen so far
};

// Follows the parser's events to know which field is being read.
class PathTracker {
 public:
  bool onEvent(json::parse_event_t event, const json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
        frames_.push_back(Frame{});
        break;
      case json::parse_event_t::array_start:
        frames_.push_back(Frame{true, 0, {}, {}});
        break;
      case json::parse_event_t::key:
        onKey(parsed.get<std::string>());
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        frames_.pop_back();
        advance();
        break;
      case json::parse_event_t::value:
        advance();
        break;
    }
    return true;
  }

  /// "shot.speed", "balls[2].x"; "scenario" at the top level.
  std::string path() const {
    std::string out;
    for (const Frame& f : frames_) {
      if (f.is_array) {
        // Appended piece by piece: g++ 12's -Wrestrict false positive at -O3 (GCC bug 105651).
        out += '[';
        out += std::to_string(f.index);
        out += ']';
      } else if (!f.key.empty()) {
        out += (out.empty() ? "" : ".") + f.key;
      }
    }
    return out.empty() ? "scenario" : out;
  }

  const std::string& duplicate() const { return duplicate_; }

 private:
  void onKey(const std::string& key) {
    Frame& top = frames_.back();
    top.key = key;
    if (!top.keys.insert(key).second && duplicate_.empty()) {
      duplicate_ = path() + ": duplicated key";
    }
  }
  // A value is complete: the enclosing array moves to its next element.
  void advance() {
    if (!frames_.empty() && frames_.back().is_array) ++frames_.back().index;
  }

  std::vector<Frame> frames_;
  std::string duplicate_;
};

// nlohmann's message without its "[json.exception.parse_error.101] " prefix.
std::string withoutPrefix(const std::string& what) {
  const auto close = what.find("] ");
  return close == std::string::npos ? what : what.substr(close + 2);
}

bool isBlank(const std::string& text) {
  return std::all_of(text.begin(), text.end(),
                     [](unsigned char c) { return std::isspace(c) != 0; });
}

}  // namespace

std::string oneLine(std::string text) {
  for (char& c : text) {
    if (std::iscntrl(static_cast<unsigned char>(c)) != 0) c = ' ';
  }
  return text;
}

Result<nlohmann::json> parseJsonDocument(const std::string& text) {
  if (isBlank(text)) return Result<json>::fail("scenario: empty input");
  PathTracker tracker;
  const json::parser_callback_t callback = [&tracker](int, json::parse_event_t event,
                                                      json& parsed) {
    return tracker.onEvent(event, parsed);
  };
  try {
    json doc = json::parse(text, callback);
    if (!tracker.duplicate().empty()) return Result<json>::fail(tracker.duplicate());
    return Result<json>::ok(std::move(doc));
  } catch (const json::out_of_range& e) {
    // The only range error while parsing is a number beyond the double range (406).
    const std::string what = e.what();
    const auto quote = what.find('\'');
    const std::string literal = quote == std::string::npos
                                    ? "an out-of-range number"
                                    : what.substr(quote + 1, what.size() - quote - 2);
    return Result<json>::fail(
        oneLine(tracker.path() + ": must be a finite number, got " + literal));
  } catch (const json::exception& e) {
    return Result<json>::fail(oneLine("scenario: invalid JSON: " + withoutPrefix(e.what())));
  }
}

}  // namespace pool::scenario
