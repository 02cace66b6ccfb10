// The gateway's lobby: client::Lobby's bounds, each entry's JSON, the message cut largest first.
#include "client/web/bounded_lobby.h"

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "client/net/lobby.h"
#include "client/web/web_json.h"

namespace pool::web {

bool BoundedLobby::update(const client::LobbyEntry& entry) {
  const client::LobbyUpdate done = lobby_.update(entry);
  if (!done.kept) {
    json_.erase(entry.match);  // not kept (a kept match moved to a full server id is gone)
    return false;
  }
  if (!done.gave_way.empty()) json_.erase(done.gave_way);
  json_[entry.match] = lobbyEntryJson(entry);
  return true;
}

void BoundedLobby::remove(const std::string& match) {
  lobby_.remove(match);
  json_.erase(match);
}

std::string BoundedLobby::message() const {
  // How many entries each server id keeps in the message: its lowest-numbered ones.
  using Json = std::map<std::string, std::string>::value_type;  // match, its JSON
  struct Share {
    const client::Lobby::Server* server;
    std::vector<const Json*> kept;  ///< lowest-numbered first
  };
  std::map<std::string, Share> shares;
  std::size_t count = 0;
  std::size_t bytes = lobbyJson({}).size();
  for (const auto& [id, server] : lobby_.servers()) {
    Share& share = shares[id];
    share.server = &server;
    for (const std::string& match : server.matches) {
      const Json& json = *json_.find(match);
      share.kept.push_back(&json);
      bytes += json.second.size() + 1;
      ++count;
    }
  }
  // Largest first: (entries kept, seen) ordered, the last one gives up its highest-numbered.
  std::set<std::tuple<std::size_t, std::uint64_t, std::string>> order;
  for (const auto& [id, share] : shares) order.emplace(share.kept.size(), share.server->seen, id);
  while ((count > limits_.served || bytes > limits_.served_bytes) && !order.empty()) {
    const auto largest = std::prev(order.end());
    const std::string id = std::get<2>(*largest);
    order.erase(largest);
    Share& share = shares.at(id);
    bytes -= share.kept.back()->second.size() + 1;
    --count;
    share.kept.pop_back();
    if (!share.kept.empty()) order.emplace(share.kept.size(), share.server->seen, id);
  }
  std::vector<const Json*> served;
  for (const auto& [id, share] : shares)
    served.insert(served.end(), share.kept.begin(), share.kept.end());
  std::sort(served.begin(), served.end(),
            [](const Json* a, const Json* b) { return client::matchOrder(a->first, b->first); });
  std::vector<const std::string*> texts;
  texts.reserve(served.size());
  for (const Json* kept : served) texts.push_back(&kept->second);
  return lobbyJson(texts);
}

}  // namespace pool::web
