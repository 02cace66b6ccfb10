// Fan-out of one spectator session to many browsers, with late join and slow browsers dropped.
#include "client/web/gateway.h"

#include <nlohmann/json.hpp>

#include "client/web/web_json.h"

namespace pool::web {
namespace {

Message share(std::string text) {
  return std::make_shared<const std::string>(std::move(text));
}

std::string errorJson(const std::string& text) {
  return nlohmann::json{{"type", "error"}, {"text", text}}.dump();
}

}  // namespace

Gateway::Gateway(client::GameClient& client, double join_retry, LobbyLimits lobby_limits)
    : client_(client), join_retry_(join_retry), lobby_entries_(lobby_limits) {}

const Message& Gateway::lobbyMessage() {
  if (!lobby_ || lobby_stale_) {
    lobby_ = share(lobby_entries_.message());
    lobby_stale_ = false;
    ++stats_.messages;
  }
  return lobby_;
}

const Message& Gateway::playersMessage() {
  if (!players_ || players_stale_) {
    players_ = share(playersJson(client_.players().fairShare(kPagePlayers), kPagePlayers));
    players_stale_ = false;
    ++stats_.messages;
  }
  return players_;
}

void Gateway::attach(std::uint64_t browser, Sink sink) {
  browsers_[browser] = Browser{std::move(sink), {}};
  sendTo(browser, lobbyMessage());
  if (client_.players().size() > 0) sendTo(browser, playersMessage());
  dropSlow();
}

void Gateway::detach(std::uint64_t browser) {
  const auto it = browsers_.find(browser);
  if (it == browsers_.end()) return;
  if (!it->second.match.empty()) {
    const auto w = watched_.find(it->second.match);
    if (w != watched_.end()) w->second.browsers.erase(browser);
  }
  browsers_.erase(it);
}

std::size_t Gateway::watchers(const std::string& match) const {
  const auto it = watched_.find(match);
  return it == watched_.end() ? 0 : it->second.browsers.size();
}

std::string Gateway::watch(std::uint64_t browser, const std::string& match) {
  const auto it = browsers_.find(browser);
  if (it == browsers_.end()) return "not connected";
  if (!match.empty() && !lobby_entries_.find(match) && !states_.count(match)) {
    ++stats_.refused;
    const std::string why = "no match '" + match + "' on the domain";
    sendTo(browser, share(errorJson(why)));
    dropSlow();
    return why;
  }
  if (it->second.match == match) return {};
  if (!it->second.match.empty()) watched_[it->second.match].browsers.erase(browser);
  it->second.match = match;
  if (match.empty()) return {};
  Watched& w = watched_[match];
  w.browsers.insert(browser);
  sendTo(browser, share(nlohmann::json{{"type", "watching"}, {"match", match}}.dump()));
  if (const Message table = tableOf(match)) sendTo(browser, table);
  if (!w.state) {
    const auto state = states_.find(match);
    if (state != states_.end()) w.state = state->second;
  }
  if (w.state) sendTo(browser, w.state);
  if (w.last_result) sendTo(browser, w.last_result);
  dropSlow();
  return {};
}

Message Gateway::tableOf(const std::string& match) {
  Watched& w = watched_[match];
  if (w.table) return w.table;
  const auto* entry = lobby_entries_.find(match);
  if (!entry) return nullptr;
  const auto cached = tables_.find(entry->table);
  if (cached != tables_.end()) return w.table = cached->second;
  auto text = tableJson(entry->table);
  if (!text) {
    // An unknown table is said once; the page then draws no table but still follows the match.
    w.table = share(errorJson("cannot draw table '" + entry->table + "': " + text.error()));
    return w.table;
  }
  if (tables_.size() < 16) tables_[entry->table] = share(*text);
  return w.table = share(std::move(*text));
}

void Gateway::step(double now) {
  for (const auto& event : client_.poll()) handle(event);
  for (auto it = watched_.begin(); it != watched_.end();) {
    Watched& w = it->second;
    if (w.browsers.empty()) {
      if (!w.empty_since) w.empty_since = now;
      if (now - *w.empty_since >= kLeaveAfter) {
        if (w.joined || w.request) client_.requestLeave(it->first);
        client_.observe(it->first, false);
        it = watched_.erase(it);
        continue;
      }
      ++it;
      continue;
    }
    w.empty_since.reset();
    if (!w.joined && now - w.sent_at >= join_retry_) {
      // One client watches many matches: each is followed (its partition read) while watched.
      client_.observe(it->first);
      w.request = client_.requestSpectate(it->first);
      w.sent_at = now;
    }
    ++it;
  }
  if (lobby_changed_ && now - lobby_sent_at_ >= kLobbyEvery) {
    lobby_sent_at_ = now;
    sendLobby();
  }
  if (players_changed_ && now - players_sent_at_ >= kLobbyEvery) {
    players_sent_at_ = now;
    players_changed_ = false;
    const Message message = playersMessage();
    for (const auto& [id, browser] : browsers_) sendTo(id, message);
  }
  dropSlow();
}

void Gateway::handle(const client::ClientEvent& event) {
  if (std::holds_alternative<client::LobbyEntry>(event) ||
      std::holds_alternative<client::MatchGone>(event)) {
    lobby_changed_ = lobby_stale_ = true;
    if (const auto* entry = std::get_if<client::LobbyEntry>(&event)) {
      if (!lobby_entries_.update(*entry)) ++stats_.lobby_refused;
    }
    if (const auto* gone = std::get_if<client::MatchGone>(&event)) {
      lobby_entries_.remove(gone->match);
      states_.erase(gone->match);
      const auto w = watched_.find(gone->match);
      if (w != watched_.end()) {
        fanOut(gone->match,
               share(nlohmann::json{
                   {"type", "gone"}, {"match", gone->match}, {"closed", gone->disposed}}
                         .dump()));
      }
    }
  } else if (const auto* answer = std::get_if<client::JoinAnswer>(&event)) {
    const auto w = watched_.find(answer->match);
    if (w != watched_.end() && w->second.request && *w->second.request == answer->request) {
      w->second.joined = answer->accepted();
      w->second.request.reset();
    }
  } else if (const auto* view = std::get_if<client::MatchView>(&event)) {
    Message message = share(stateJson(*view));
    if (states_.size() < 4096 || states_.count(view->match)) states_[view->match] = message;
    const auto w = watched_.find(view->match);
    if (w != watched_.end()) {
      w->second.state = message;
      fanOut(view->match, message);
    }
  } else if (const auto* report = std::get_if<client::ShotReport>(&event)) {
    const auto w = watched_.find(report->match);
    if (w == watched_.end() || !report->accepted) return;
    Message message = share(resultJson(*report));
    if (report->final()) w->second.last_result = message;
    fanOut(report->match, message);
  } else if (std::holds_alternative<protocol::PlayerStats>(event)) {
    players_changed_ = players_stale_ = true;
  } else if (const auto* frame = std::get_if<client::TableFrame>(&event)) {
    if (watched_.count(frame->match)) fanOut(frame->match, share(frameJson(*frame)));
  }
  dropSlow();
}

void Gateway::sendTo(std::uint64_t browser, const Message& message) {
  const auto it = browsers_.find(browser);
  if (it == browsers_.end() || slow_.count(browser)) return;
  ++stats_.deliveries;
  if (!it->second.sink(message)) slow_.insert(browser);
}

void Gateway::fanOut(const std::string& match, const Message& message) {
  const auto w = watched_.find(match);
  if (w == watched_.end()) return;
  ++stats_.messages;
  for (const std::uint64_t browser : w->second.browsers) sendTo(browser, message);
}

void Gateway::sendLobby() {
  const Message message = lobbyMessage();
  lobby_changed_ = false;
  for (const auto& [id, browser] : browsers_) sendTo(id, message);
}

void Gateway::dropSlow() {
  for (const std::uint64_t browser : slow_) detach(browser);
  slow_.clear();
}

std::optional<std::string> parseWatch(const std::string& text, std::string& error) {
  const auto json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) {
    error = "not a JSON object";
    return std::nullopt;
  }
  const auto it = json.find("watch");
  if (it == json.end() || !it->is_string() || json.size() != 1) {
    error = "expected {\"watch\":\"<match id>\"}";
    return std::nullopt;
  }
  const std::string match = it->get<std::string>();
  if (match.size() > 64) {
    error = "a match id has at most 64 characters";
    return std::nullopt;
  }
  for (unsigned char c : match) {
    if (c < 0x21 || c > 0x7e) {
      error = "a match id is printable ASCII without spaces";
      return std::nullopt;
    }
  }
  return match;
}

}  // namespace pool::web
