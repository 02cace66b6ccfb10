// Every key and mouse action of the window, as the help overlay (F1) and the README list them.
#pragma once

#include <string_view>
#include <vector>

namespace pool::app {

/// One line of the help: when it applies, the keys, what they do.
struct KeyHelp {
  std::string_view when;
  std::string_view keys;
  std::string_view does;
};

/// The whole list, in the order the help shows it.
const std::vector<KeyHelp>& keyHelp();

}  // namespace pool::app
