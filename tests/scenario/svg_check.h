// Light checks of the plot's SVG text: well-formed tags, and counting elements by class.
#pragma once

#include <string>
#include <vector>

namespace pool::scenario::testing {

/// Number of non-overlapping occurrences of `needle` in `text`.
inline std::size_t countOf(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + needle.size()))
    ++n;
  return n;
}

/// "" if every tag opens and closes in order (self-closing tags count as both), otherwise the
/// problem.
inline std::string tagBalance(const std::string& svg) {
  std::vector<std::string> open;
  for (auto lt = svg.find('<'); lt != std::string::npos; lt = svg.find('<', lt + 1)) {
    const auto gt = svg.find('>', lt);
    if (gt == std::string::npos) return "unterminated tag";
    const std::string tag = svg.substr(lt + 1, gt - lt - 1);
    if (tag.empty()) return "empty tag";
    if (tag.back() == '/' || tag.front() == '?' || tag.front() == '!') continue;
    const std::string name = tag.substr(tag.front() == '/' ? 1 : 0,
                                        tag.find_first_of(" \n\t") - (tag.front() == '/' ? 1 : 0));
    if (tag.front() != '/') {
      open.push_back(name);
    } else if (open.empty() || open.back() != name) {
      return "unexpected </" + name + ">";
    } else {
      open.pop_back();
    }
  }
  return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

}  // namespace pool::scenario::testing
