// Fan-out of one spectator session to many browsers, with late join and slow browsers dropped.
#include "client/web/gateway.h"

#include <nlohmann/json.hpp>

#include "client/web/replay_json.h"
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

const Message& Gateway::tournamentsMessage() {
  if (!tournaments_message_ || tournaments_stale_) {
    std::vector<const protocol::TournamentView*> list;
    for (const auto& [id, view] : client_.tournaments()) list.push_back(&view);
    tournaments_message_ = share(tournamentsJson(list));
    tournaments_stale_ = false;
    ++stats_.messages;
  }
  return tournaments_message_;
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
  browsers_[browser] = Browser{std::move(sink), {}, -1e9};
  sendTo(browser, lobbyMessage());
  if (client_.players().size() > 0) sendTo(browser, playersMessage());
  if (!client_.tournaments().empty()) sendTo(browser, tournamentsMessage());
  dropSlow();
}

void Gateway::detach(std::uint64_t browser) {
  const auto it = browsers_.find(browser);
  if (it == browsers_.end()) return;
  for (auto r = replays_.begin(); r != replays_.end();) {
    r->second.browsers.erase(browser);
    r = r->second.browsers.empty() ? replays_.erase(r) : std::next(r);
  }
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

std::string Gateway::replay(std::uint64_t browser, const std::string& match, std::uint32_t shot) {
  const auto self = browsers_.find(browser);
  if (self == browsers_.end()) return "not connected";
  // A browser asks at most once every kReplayGap s: the gateway's one key has a share of the
  // server's answers that every browser shares.
  if (now_ - self->second.replay_at < kReplayGap) {
    const std::string why = "one replay at a time: wait a moment";
    sendTo(browser, share(errorJson(why)));
    dropSlow();
    return why;
  }
  self->second.replay_at = now_;
  // One replay a browser waits for: a new one replaces it.
  for (auto it = replays_.begin(); it != replays_.end();) {
    it->second.browsers.erase(browser);
    it = it->second.browsers.empty() ? replays_.erase(it) : std::next(it);
  }
  const auto cached = replay_cache_.find({match, shot});
  if (cached != replay_cache_.end()) {
    sendTo(browser, tableNamed(cached->second.table));
    sendTo(browser, cached->second.message);
    dropSlow();
    return {};
  }
  for (auto& [request, pending] : replays_) {
    if (pending.match == match && pending.shot == shot) {
      pending.browsers.insert(browser);
      return {};
    }
  }
  if (!askReplay(match, shot, {browser}, 1)) {
    const std::string why = "cannot ask for a replay of " + match;
    sendTo(browser, share(errorJson(why)));
    dropSlow();
    return why;
  }
  return {};
}

bool Gateway::askReplay(const std::string& match, std::uint32_t shot,
                        std::set<std::uint64_t> browsers, int tries) {
  const auto request = client_.requestHistory(match, shot, 1);
  if (!request) return false;
  while (replays_.size() >= kMaxPendingReplays) {
    // The oldest gives way; its browsers are told.
    const Message error = share(errorJson("too many replays asked at once: ask again"));
    for (const std::uint64_t b : replays_.begin()->second.browsers) sendTo(b, error);
    replays_.erase(replays_.begin());
  }
  replays_[*request] = PendingReplay{match, shot, std::move(browsers), now_, tries};
  return true;
}

void Gateway::answerReplay(const protocol::HistoryShot& shot) {
  const auto it = replays_.find(shot.request);
  // Only the answer about what was asked (the client's key checked it was asked by us).
  if (it == replays_.end() || shot.match != it->second.match ||
      (shot.found && shot.shot_number != it->second.shot)) {
    return;
  }
  PendingReplay pending = std::move(it->second);
  replays_.erase(it);
  const Message message = share(replayJson(shot, pending.shot));
  ++stats_.messages;
  Message drawing;
  if (shot.found) {
    drawing = tableNamed(shot.table);
    const std::pair<std::string, std::uint32_t> key{pending.match, pending.shot};
    if (!replay_cache_.count(key)) {
      replay_order_.push_back(key);
      while (replay_order_.size() > kReplayCache) {
        replay_cache_.erase(replay_order_.front());
        replay_order_.pop_front();
      }
    }
    replay_cache_[key] = CachedReplay{message, shot.table};
  }
  for (const std::uint64_t browser : pending.browsers) {
    if (drawing) sendTo(browser, drawing);
    sendTo(browser, message);
  }
}

Message Gateway::tableNamed(const std::string& name) {
  const auto cached = tables_.find(name);
  if (cached != tables_.end()) return cached->second;
  auto text = tableJson(name);
  if (!text) return share(errorJson("cannot draw table '" + name + "': " + text.error()));
  Message drawing = share(std::move(*text));
  if (tables_.size() < 16) tables_[name] = drawing;
  return drawing;
}

Message Gateway::tableOf(const std::string& match) {
  Watched& w = watched_[match];
  if (w.table) return w.table;
  const auto* entry = lobby_entries_.find(match);
  if (!entry) return nullptr;
  // An unknown table is said once; the page then draws no table but still follows the match.
  return w.table = tableNamed(entry->table);
}

void Gateway::step(double now) {
  now_ = now;
  for (const auto& event : client_.poll()) handle(event);
  for (auto it = replays_.begin(); it != replays_.end();) {
    if (now - it->second.sent_at < kReplayRetry) {
      ++it;
      continue;
    }
    PendingReplay pending = std::move(it->second);
    it = replays_.erase(it);
    if (pending.tries >= kReplayTries ||
        !askReplay(pending.match, pending.shot, pending.browsers, pending.tries + 1)) {
      const Message error = share(errorJson("no answer from the server of " + pending.match +
                                            " for shot " + std::to_string(pending.shot)));
      for (const std::uint64_t browser : pending.browsers) sendTo(browser, error);
    }
  }
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
  if (tournaments_changed_ && now - tournaments_sent_at_ >= kLobbyEvery) {
    tournaments_sent_at_ = now;
    tournaments_changed_ = false;
    const Message message = tournamentsMessage();
    for (const auto& [id, browser] : browsers_) sendTo(id, message);
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
  } else if (std::holds_alternative<protocol::TournamentView>(event)) {
    tournaments_changed_ = tournaments_stale_ = true;
  } else if (const auto* shot = std::get_if<protocol::HistoryShot>(&event)) {
    answerReplay(*shot);
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

namespace {

/// A match id as a browser may send it: at most 64 printable ASCII characters without spaces.
bool validMatchText(const std::string& match, std::string& error) {
  if (match.size() > 64) {
    error = "a match id has at most 64 characters";
    return false;
  }
  for (unsigned char c : match) {
    if (c < 0x21 || c > 0x7e) {
      error = "a match id is printable ASCII without spaces";
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<BrowserRequest> parseRequest(const std::string& text, std::string& error) {
  const auto json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) {
    error = "not a JSON object";
    return std::nullopt;
  }
  constexpr const char* kExpected =
      "expected {\"watch\":\"<match id>\"} or {\"replay\":{\"match\":\"<match id>\",\"shot\":n}}";
  if (json.size() != 1) {
    error = kExpected;
    return std::nullopt;
  }
  if (const auto it = json.find("watch"); it != json.end() && it->is_string()) {
    std::string match = it->get<std::string>();
    if (!validMatchText(match, error)) return std::nullopt;
    return WatchRequest{std::move(match)};
  }
  const auto it = json.find("replay");
  if (it == json.end() || !it->is_object() || it->size() != 2 || !it->contains("match") ||
      !it->contains("shot") || !(*it)["match"].is_string() || !(*it)["shot"].is_number_unsigned()) {
    error = kExpected;
    return std::nullopt;
  }
  std::string match = (*it)["match"].get<std::string>();
  if (match.empty()) {
    error = "a replay names a match";
    return std::nullopt;
  }
  if (!validMatchText(match, error)) return std::nullopt;
  const auto shot = (*it)["shot"].get<std::uint64_t>();
  if (shot < 1 || shot > 0xffffffffu) {
    error = "a shot number counts from 1";
    return std::nullopt;
  }
  return ReplayRequest{std::move(match), static_cast<std::uint32_t>(shot)};
}

}  // namespace pool::web
