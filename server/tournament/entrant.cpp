// The checks on a tournament's field: its size, the ids, the names and the ratings.
#include "server/tournament/entrant.h"

#include "core/text.h"

#include <cmath>
#include <set>

namespace pool::tournament {

Check<> checkEntrants(const std::vector<Entrant>& entrants) {
  const auto refuse = [](std::string why) {
    return Check<>::refuse("bad_entrants", "tournament entrants: " + std::move(why));
  };
  const auto count = entrants.size();
  if (count < static_cast<std::size_t>(kMinEntrants) ||
      count > static_cast<std::size_t>(kMaxEntrants)) {
    return refuse(std::to_string(count) + " entrants; a tournament takes " +
                  std::to_string(kMinEntrants) + " to " + std::to_string(kMaxEntrants));
  }
  std::set<std::string> ids;
  for (std::size_t i = 0; i < count; ++i) {
    const Entrant& e = entrants[i];
    const std::string which = "entrant " + std::to_string(i);
    if (e.id.empty()) return refuse(which + " has an empty id");
    if (!isCleanUtf8(e.id, kMaxTextBytes)) {
      return refuse(which + "'s id is not UTF-8 text of at most " + std::to_string(kMaxTextBytes) +
                    " bytes");
    }
    if (e.name.empty()) return refuse(which + " (" + e.id + ") has an empty name");
    if (!isCleanUtf8(e.name, kMaxTextBytes)) {
      return refuse(which + " (" + e.id + ")'s name is not UTF-8 text of at most " +
                    std::to_string(kMaxTextBytes) + " bytes");
    }
    if (!std::isfinite(e.rating)) return refuse(which + " (" + e.id + ") has no finite rating");
    if (!ids.insert(e.id).second) return refuse(which + " repeats the id " + e.id);
  }
  return Check<>::pass();
}

}  // namespace pool::tournament
