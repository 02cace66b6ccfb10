// Join requests, shots and polling of the protocol's topics.
#include "client/net/game_client.h"

#include <algorithm>
#include <cstdio>
#include <random>

#include "core/text.h"
#include "protocol/command_signature.h"
#include "protocol/protocol_version.h"

namespace pool::client {

std::string randomClientId() {
  std::random_device device;
  const std::uint64_t value = (static_cast<std::uint64_t>(device()) << 32) ^ device();
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

GameClient::GameClient(ClientOptions options, std::optional<protocol::KeyPair> key)
    : options_(std::move(options)),
      key_(key ? *key : protocol::generateKeyPair()),
      pins_(options_.server_pins) {
  if (options_.client_id.empty()) options_.client_id = randomClientId();
  if (!pins_.fileProblem().empty()) note("server keys: " + pins_.fileProblem());
  transport_ = std::make_unique<net::ClientTransport>(
      options_.domain, [this](const protocol::SealedSample& s) { return checkServer(s); });
}

GameClient::~GameClient() = default;

void GameClient::problem(const std::string& what) {
  ++unreadable_;
  last_problem_ = what;
  note(what);
}

void GameClient::note(const std::string& line, bool is_problem) {
  // A flood of forged samples logs each kind of refusal once; the rest are only counted.
  constexpr std::size_t kMaxLogged = 256;
  if (logged_.size() >= kMaxLogged || !logged_.insert(line).second) return;
  if (options_.log) {
    options_.log(line, is_problem);
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

Check<> GameClient::checkServer(const protocol::SealedSample& sample) {
  if (auto ok = protocol::checkSeal(sample); !ok) return ok;
  const std::string server = escapedForLog(sample.server);
  switch (pins_.check(sample.server, sample.server_key)) {
    case PinCheck::Same:
      return Check<>::pass();
    case PinCheck::FirstSight:
      note("server '" + server + "': key " + protocol::fingerprint(sample.server_key) +
               " pinned at first sight" +
               (options_.server_pins.empty() ? "" : " (" + options_.server_pins.string() + ")"),
           false);
      if (!pins_.fileProblem().empty()) note("server keys: " + pins_.fileProblem());
      return Check<>::pass();
    case PinCheck::Changed:
      break;
    case PinCheck::Refused:
      return Check<>::refuse("bad_server_id", std::string(protocol::toString(sample.kind)) +
                                                  " from server '" + server +
                                                  "' dropped: not a valid server id");
  }
  const auto* pinned = pins_.pinned(sample.server);
  return Check<>::refuse(
      "key_changed",
      std::string(protocol::toString(sample.kind)) + " from server '" + server +
          "' dropped: signed by key " + protocol::fingerprint(sample.server_key) +
          ", but the key pinned for that server is " +
          protocol::fingerprint(std::span<const std::uint8_t>(pinned->data(), pinned->size())) +
          " (the server's key changed: if its database was replaced on purpose, "
          "forget the old key with --forget-server-key " +
          server + ")");
}

Check<> GameClient::checkJump(const std::string& match, const char* what, std::uint32_t revision,
                              std::uint32_t shot_number) const {
  const MatchView* last = state(match);
  if (!last) return Check<>::pass();
  const std::string where = std::string(what) + " of " + escapedForLog(match) + " dropped: ";
  if (revision > last->revision && revision - last->revision > kMaxRevisionJump) {
    return Check<>::refuse("revision_jump", where + "revision " + std::to_string(revision) +
                                                " after " + std::to_string(last->revision) +
                                                " is an impossible jump");
  }
  if (shot_number > last->shot_number && shot_number - last->shot_number > kMaxShotJump) {
    return Check<>::refuse("shot_jump", where + "shot " + std::to_string(shot_number) + " after " +
                                            std::to_string(last->shot_number) +
                                            " is an impossible jump");
  }
  return Check<>::pass();
}

std::uint32_t GameClient::sendJoin(const std::string& match, JoinAction action, int seat,
                                   std::uint64_t token, const std::optional<Opening>& opening) {
  protocol::SeatRequest r;
  r.client = options_.client_id;
  r.request = next_request_++;
  r.protocol_version = protocol::kProtocolVersion;
  r.match = match;
  r.action = action;
  r.seat = seat;
  r.name = options_.name;
  r.token = token;
  if (action == JoinAction::Seat) r.settings = table_settings_;
  if (opening) {
    r.settings = opening->first;
    r.opening = opening->second;
  }
  const std::uint32_t number = r.request;
  send(r);
  pending_[number] = PendingJoin{std::move(r), false};
  refollow();
  return number;
}

void GameClient::observe(const std::string& match, bool on) {
  if (on ? observed_.insert(match).second : observed_.erase(match) > 0) refollow();
}

void GameClient::refollow() {
  std::vector<std::string> wanted;
  if (seat_) wanted.push_back(seat_->match);
  if (watching_) wanted.push_back(*watching_);
  wanted.insert(wanted.end(), observed_.begin(), observed_.end());
  for (auto it = pending_.rbegin(); it != pending_.rend(); ++it) {
    const auto& r = it->second.request;
    if (r.action != JoinAction::Leave && r.action != JoinAction::Enter &&
        r.match != protocol::kNewMatch) {
      wanted.push_back(r.match);
    }
  }
  std::set<std::string> follow;
  for (const auto& match : wanted) {
    if (follow.size() >= net::kMaxFollowed) break;
    follow.insert(match);
  }
  if (follow == transport_->followed()) return;
  if (auto why = transport_->follow(follow); !why.empty()) note("following matches: " + why);
  std::erase_if(states_, [&](const auto& entry) { return !follow.count(entry.first); });
}

void GameClient::send(protocol::SeatRequest& r) {
  r.public_key = key().publicKey();
  if (protocol::changesSeat(r)) {
    r.seq = ++last_seq_;
    protocol::signSeatRequest(r, key());
  }
  if (auto error = transport_->send(r); !error.empty()) last_problem_ = "join request: " + error;
}

std::uint32_t GameClient::requestSeat(const std::string& match, int seat) {
  return sendJoin(match, JoinAction::Seat, seat, 0);
}

std::uint32_t GameClient::requestSpectate(const std::string& match) {
  return sendJoin(match, JoinAction::Spectate, -1, 0);
}

std::uint32_t GameClient::requestRejoin(const std::string& match, std::uint64_t token, int seat) {
  // Continue above the numbers the seat's key used before (a restarted process starts at 0).
  if (const MatchView* view = state(match); view && (seat == 0 || seat == 1)) {
    noteSequence(view->seats[static_cast<std::size_t>(seat)].last_seq);
  }
  return sendJoin(match, JoinAction::Rejoin, seat, token);
}

std::uint32_t GameClient::requestLeave(const std::string& match) {
  const bool seated = seat_ && seat_->match == match;
  return sendJoin(match, JoinAction::Leave, seated ? seat_->seat : -1, seated ? seat_->token : 0);
}

std::uint32_t GameClient::requestRematch() {
  if (!seat_) return 0;
  return sendJoin(seat_->match, JoinAction::Rematch, seat_->seat, seat_->token);
}

std::uint32_t GameClient::requestConcede() {
  if (!seat_) return 0;
  return sendJoin(seat_->match, JoinAction::Concede, seat_->seat, seat_->token);
}

template <class Message, class Sign>
Result<std::uint32_t> GameClient::sendSigned(Message message, std::uint32_t seq, Sign sign,
                                             const char* what) {
  message.match = seat_->match;
  message.seat = seat_->seat;
  message.seat_token = seat_->token;
  message.seq = seq;
  sign(message, key());
  if (auto error = transport_->send(message); !error.empty()) {
    return Result<std::uint32_t>::fail(std::string(what) + ": " + error);
  }
  return Result<std::uint32_t>::ok(seq);
}

Result<std::uint32_t> GameClient::shoot(protocol::ShotRequest request) {
  if (!seat_) return Result<std::uint32_t>::fail("no seat held");
  return sendSigned(std::move(request), ++last_seq_, protocol::signCommand, "shot command");
}

Result<std::uint32_t> GameClient::practice(protocol::PracticeRequest request) {
  if (!seat_) return Result<std::uint32_t>::fail("no seat held");
  return sendSigned(std::move(request), ++last_seq_, protocol::signPractice, "practice command");
}

Result<std::uint32_t> GameClient::sendAim(protocol::AimSample aim) {
  if (!seat_) return Result<std::uint32_t>::fail("no seat held");
  if (aim.shot_number != aim_shot_) {
    aim_shot_ = aim.shot_number;
    aim_seq_ = 0;  // an aim's number counts within its turn
  }
  return sendSigned(std::move(aim), ++aim_seq_, protocol::signAim, "aim");
}

void GameClient::noteSequence(std::uint32_t seq) {
  last_seq_ = std::max(last_seq_, seq);
}

void GameClient::wait(std::chrono::nanoseconds timeout) const {
  transport_->wait(timeout);
}

std::vector<ClientEvent> GameClient::poll() {
  std::vector<ClientEvent> out;
  pollLobby(out);
  pollPlayers(out);
  pollReplies(out);
  pollStates(out);
  pollResults(out);
  pollFrames(out);
  pollAims(out);
  pollHistory(out);
  pollTournaments(out);
  return out;
}

std::uint32_t GameClient::requestEnter(const std::string& tournament) {
  return sendJoin(tournament, JoinAction::Enter, -1, 0);
}

std::uint32_t GameClient::requestOpenTournament(const protocol::MatchSettings& settings,
                                                const protocol::TournamentOpening& opening) {
  return sendJoin(protocol::kNewMatch, JoinAction::Enter, -1, 0, Opening{settings, opening});
}

void GameClient::pollTournaments(std::vector<ClientEvent>& out) {
  for (auto& view : transport_->takeTournaments()) {
    if (!view) {
      problem(view.error());
      continue;
    }
    // A tournament waits until its server is in the lobby (the lobby's entries may come later),
    // the latest kMaxTournaments of them.
    if (!waiting_tournaments_.count(view->tournament) &&
        waiting_tournaments_.size() >= kMaxTournaments) {
      waiting_tournaments_.erase(waiting_tournaments_.begin());
    }
    waiting_tournaments_[view->tournament] = std::move(*view);
  }
  for (auto it = waiting_tournaments_.begin(); it != waiting_tournaments_.end();) {
    const protocol::TournamentView& view = it->second;
    // Kept only for a server the lobby lists, and only so many (a flood of invented ids is no
    // one's tournaments).
    if (!lobby_.servers().count(view.server)) {
      ++it;
      continue;
    }
    // A tournament's id names its server ("<server id>-t<n>"): another server cannot publish one
    // under it (the samples' signatures are pinned per server id).
    if (view.tournament.rfind(view.server + "-t", 0) != 0) {
      problem("tournament " + view.tournament + " published as server " + view.server);
      it = waiting_tournaments_.erase(it);
      continue;
    }
    if (!tournaments_.count(view.tournament) && tournaments_.size() >= kMaxTournaments) {
      // Full: one that is over makes room.
      for (auto old = tournaments_.begin(); old != tournaments_.end(); ++old) {
        if (old->second.phase == protocol::TournamentPhase::Finished ||
            old->second.phase == protocol::TournamentPhase::Cancelled) {
          tournaments_.erase(old);
          break;
        }
      }
    }
    if (tournaments_.count(view.tournament) || tournaments_.size() < kMaxTournaments) {
      tournaments_[view.tournament] = view;
      out.emplace_back(view);
    }
    it = waiting_tournaments_.erase(it);
  }
}

void GameClient::openHistory() {
  transport_->openHistory();
}

Result<std::uint32_t> GameClient::requestHistory(const std::string& match, std::uint32_t first,
                                                 std::uint32_t count) {
  protocol::HistoryRequest r;
  r.client = options_.client_id;
  r.request = next_request_++;
  r.match = match;
  r.first_shot = first;
  r.count = count;
  if (auto ok = protocol::checkHistoryRequest(r); !ok) {
    return Result<std::uint32_t>::fail("history request: " + ok.error());
  }
  protocol::signHistory(r, key_);
  if (auto why = transport_->send(r); !why.empty()) {
    return Result<std::uint32_t>::fail("history request: " + why);
  }
  history_requests_.push_back(r.request);
  while (history_requests_.size() > kHistoryRequestsKept) history_requests_.pop_front();
  return Result<std::uint32_t>::ok(r.request);
}

void GameClient::pollHistory(std::vector<ClientEvent>& out) {
  for (auto& shot : transport_->takeHistory()) {
    if (!shot) {
      problem(shot.error());
      continue;
    }
    // Everyone's answers travel on the one topic: only those to our own requests, signed with
    // our own key (a client id and request number are anyone's to reuse), are ours.
    if (shot->client != options_.client_id ||
        !std::equal(shot->asker.begin(), shot->asker.end(), key_.public_key.begin(),
                    key_.public_key.end()) ||
        std::find(history_requests_.begin(), history_requests_.end(), shot->request) ==
            history_requests_.end()) {
      continue;
    }
    out.emplace_back(std::move(*shot));
  }
}

const MatchView* GameClient::state(const std::string& match) const {
  const auto it = states_.find(match);
  return it == states_.end() ? nullptr : &it->second;
}

void GameClient::pollLobby(std::vector<ClientEvent>& out) {
  for (auto& event : transport_->takeLobby()) {
    if (!event) {
      problem(event.error());
      continue;
    }
    if (const auto* gone = std::get_if<MatchGone>(&*event)) {
      lobby_.remove(gone->match);
      out.emplace_back(*gone);
      continue;
    }
    const auto& entry = std::get<LobbyEntry>(*event);
    lobby_.update(entry);
    out.emplace_back(entry);
  }
}

void GameClient::pollPlayers(std::vector<ClientEvent>& out) {
  for (auto& stats : transport_->takePlayerStats()) {
    if (!stats) {
      problem(stats.error());
      continue;
    }
    // A record counts once its server id is one the lobby lists (its tables open): until then
    // it waits, a bounded few (a record of a server id nobody's lobby shows is never shown).
    waiting_players_.push_back(std::move(*stats));
    if (waiting_players_.size() > kMaxWaitingPlayers) waiting_players_.pop_front();
  }
  for (auto it = waiting_players_.begin(); it != waiting_players_.end();) {
    if (!lobby_.servers().count(it->server)) {
      ++it;
      continue;
    }
    players_.update(*it);
    out.emplace_back(std::move(*it));
    it = waiting_players_.erase(it);
  }
}

bool GameClient::accept(const JoinAnswer& answer) {
  const auto it = pending_.find(answer.request);
  PendingJoin& pending = it->second;
  // The server says which numbers the key has used: ours continue above them.
  if (pending.request.seq != 0) noteSequence(answer.last_seq);
  if (answer.outcome == JoinOutcome::StaleSequence && !pending.retried) {
    // A restarted process with a kept key: the same request once more, numbered above the
    // server's floor (its answer carries the same request number).
    pending.retried = true;
    send(pending.request);
    return false;
  }
  const protocol::SeatRequest sent = std::move(pending.request);
  pending_.erase(it);
  if (!answer.accepted()) return true;
  if (sent.action == JoinAction::Seat || sent.action == JoinAction::Rejoin) {
    noteSequence(seen_seq_[{answer.match, answer.seat}]);
    seat_ = SeatHolding{answer.match, answer.seat, answer.token};
    if (watching_ != answer.match) watching_.reset();
  } else if (sent.action == JoinAction::Spectate) {
    watching_ = answer.match;
  } else if (sent.action == JoinAction::Leave) {
    if (seat_ && seat_->match == answer.match) seat_.reset();
    if (watching_ == answer.match) watching_.reset();
  }
  return true;
}

void GameClient::pollReplies(std::vector<ClientEvent>& out) {
  for (auto& answer : transport_->takeReplies()) {
    if (!answer) {
      problem(answer.error());
      continue;
    }
    if (answer->client != options_.client_id) continue;
    // Replies to requests of an earlier session with the same id, or repeated ones, are stale.
    if (!pending_.count(answer->request)) continue;
    if (accept(*answer)) out.emplace_back(std::move(*answer));
  }
  refollow();
}

bool GameClient::goesBack(std::uint32_t& floor, std::uint32_t number, const std::string& why) {
  if (number < floor) {
    ++stale_;
    note(why);
    return true;
  }
  floor = number;
  return false;
}

namespace {

/// `floors[key]`, the map started over first when it is full.
template <class Key>
std::uint32_t& floorOf(std::map<Key, std::uint32_t>& floors, const Key& key, std::size_t max) {
  if (floors.size() >= max && !floors.count(key)) floors.clear();
  return floors[key];
}

}  // namespace

void GameClient::pollStates(std::vector<ClientEvent>& out) {
  // Per match: states taken in this poll, and whether one was dropped as older.
  std::map<std::string, std::pair<std::uint32_t, bool>> taken;
  for (auto& view : transport_->takeStates()) {
    if (!view) {
      problem(view.error());
      continue;
    }
    auto& [count, dropped_older] = taken[view->match];
    ++count;
    if (auto ok = checkJump(view->match, "MatchState", view->revision, view->shot_number); !ok) {
      problem(ok.error());
      continue;
    }
    // Only forward: an older state, genuine and signed (a replay), would turn the match back.
    // Revisions go on across a server's restarts (stored with the match).
    if (goesBack(floorOf(state_floor_, view->match, kMaxFloors), view->revision,
                 "MatchState of " + escapedForLog(view->match) +
                     " dropped: older than the revision already taken (a replay?)")) {
      dropped_older = true;
      continue;
    }
    states_[view->match] = *view;
    out.emplace_back(std::move(*view));
  }
  // A reader keeps the last kReaderDepth states: replays that filled it since the last poll may
  // have pushed out a newer genuine one, which the server would not send again until its next
  // change. Then the match is followed afresh, and the server's writer hands its latest state
  // over again (at most once a second per match, whatever a stranger keeps sending).
  const auto now = std::chrono::steady_clock::now();
  for (const auto& [match, seen] : taken) {
    if (seen.first < net::kReaderDepth || !seen.second) continue;
    if (refetched_.size() >= kMaxFloors && !refetched_.count(match)) refetched_.clear();
    auto [at, first] = refetched_.try_emplace(match, now);
    if (!first && now - at->second < std::chrono::seconds(1)) continue;
    at->second = now;
    if (auto why = transport_->refetch(match); !why.empty()) continue;
    note("MatchState of " + escapedForLog(match) + ": " + std::to_string(seen.first) +
         " states at once, older ones among them (replays?): following the match afresh for "
         "its latest state");
  }
}

void GameClient::pollResults(std::vector<ClientEvent>& out) {
  for (auto& report : transport_->takeResults()) {
    if (!report) {
      problem(report.error());
      continue;
    }
    if (auto ok = checkJump(report->match, "ShotResult", 0, report->shot_number); !ok) {
      problem(ok.error());
      continue;
    }
    if (goesBack(floorOf(result_floor_, std::pair(report->match, int{report->seat}), kMaxFloors),
                 report->shot_number,
                 "ShotResult of " + escapedForLog(report->match) +
                     " dropped: of an earlier shot than one already taken (a replay?)")) {
      continue;
    }
    const std::pair<std::string, int> seat_key(report->match, report->seat);
    if (results_seen_.size() >= kMaxFloors && !results_seen_.count(seat_key)) {
      results_seen_.clear();
    }
    auto& seen_here = results_seen_[seat_key];
    const ResultSeen key{report->seq, report->shot_number, report->accepted, report->final()};
    if (std::find(seen_here.begin(), seen_here.end(), key) != seen_here.end()) {
      ++stale_;
      note("ShotResult of " + escapedForLog(report->match) +
           " dropped: the same as one already taken (a replay?)");
      continue;
    }
    if (seen_here.size() >= kResultsRemembered) seen_here.erase(seen_here.begin());
    seen_here.push_back(key);
    // Only a number the seat's own key used up counts: anyone may send a command with any
    // number, and its refusal must not move ours (up to a wrap-around, say).
    if (report->usesUpSequence()) {
      auto& seen = seen_seq_[{report->match, report->seat}];
      seen = std::max(seen, report->seq);
      if (seat_ && report->match == seat_->match && report->seat == seat_->seat) {
        noteSequence(report->seq);
      }
    }
    out.emplace_back(std::move(*report));
  }
}

void GameClient::pollFrames(std::vector<ClientEvent>& out) {
  for (auto& frame : transport_->takeFrames()) {
    if (!frame) {
      problem(frame.error());
      continue;
    }
    if (auto ok = checkJump(frame->match, "TableSnapshot", 0, frame->shot_number); !ok) {
      problem(ok.error());
      continue;
    }
    if (goesBack(floorOf(frame_floor_, frame->match, kMaxFloors), frame->shot_number,
                 "TableSnapshot of " + escapedForLog(frame->match) +
                     " dropped: of an earlier shot than one already taken (a replay?)")) {
      continue;
    }
    out.emplace_back(std::move(*frame));
  }
}

Check<> GameClient::checkAim(const protocol::AimSample& aim) {
  const MatchView* view = state(aim.match);
  const std::string where = "aim of " + escapedForLog(aim.match) + " dropped: ";
  if (!view) return Check<>::refuse("no_state", where + "no state of that match");
  if (!inPlay(view->phase) || aim.seat != view->shooter)
    return Check<>::refuse("not_shooter", where + "not the shooter's");
  if (aim.shot_number != view->shot_number)
    return Check<>::refuse("other_turn", where + "of another turn");
  const auto seen = aims_seen_.find(aim.match);
  if (seen != aims_seen_.end() && seen->second.first == aim.shot_number &&
      aim.seq <= seen->second.second) {
    return Check<>::refuse("replayed", where + "not newer than the last one (a replay)");
  }
  return Check<>::pass();
}

void GameClient::pollAims(std::vector<ClientEvent>& out) {
  for (auto& aim : transport_->takeAims()) {
    ++aim_dropped_;
    if (!aim) {
      problem(aim.error());
      continue;
    }
    if (auto ok = checkAim(*aim); !ok) {
      note(ok.error());
      continue;
    }
    --aim_dropped_;
    aims_seen_[aim->match] = {aim->shot_number, aim->seq};
    out.emplace_back(std::move(*aim));
  }
}

}  // namespace pool::client
