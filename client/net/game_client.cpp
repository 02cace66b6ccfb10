// Join requests, shots and polling of the protocol's topics.
#include "client/net/game_client.h"

#include <cstdio>
#include <random>

#include "client/net/client_endpoints.h"
#include "client/net/wire_read.h"
#include "net/command_signature.h"
#include "net/convert.h"
#include "net/wire_fields.h"

namespace pool::client {

std::string randomClientId() {
  std::random_device device;
  const std::uint64_t value = (static_cast<std::uint64_t>(device()) << 32) ^ device();
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

GameClient::GameClient(ClientOptions options, std::optional<net::KeyPair> key)
    : options_(std::move(options)), key_(key ? *key : net::generateKeyPair()) {
  if (options_.client_id.empty()) options_.client_id = randomClientId();
  endpoints_ = std::make_unique<ClientEndpoints>(options_.domain);
}

GameClient::~GameClient() = default;

void GameClient::problem(const std::string& what) {
  ++unreadable_;
  last_problem_ = what;
}

std::uint32_t GameClient::sendJoin(const std::string& match, JoinAction action, int seat,
                                   std::uint64_t token) {
  JoinRequestFields fields{
      options_.client_id, next_request_++, match, action, seat, options_.name, token,
      key().publicKey()};
  pending_[fields.request] = action;
  if (auto status = endpoints_->join_requests.write(*toWire(fields)); !status) {
    last_problem_ = "join request: " + status.error;
  }
  return fields.request;
}

std::uint32_t GameClient::requestSeat(const std::string& match, int seat) {
  return sendJoin(match, JoinAction::Seat, seat, 0);
}

std::uint32_t GameClient::requestSpectate(const std::string& match) {
  return sendJoin(match, JoinAction::Spectate, -1, 0);
}

std::uint32_t GameClient::requestRejoin(const std::string& match, std::uint64_t token) {
  return sendJoin(match, JoinAction::Rejoin, -1, token);
}

std::uint32_t GameClient::requestLeave(const std::string& match) {
  const bool seated = seat_ && seat_->match == match;
  return sendJoin(match, JoinAction::Leave, seated ? seat_->seat : -1, seated ? seat_->token : 0);
}

std::uint32_t GameClient::requestRematch() {
  if (!seat_) return 0;
  return sendJoin(seat_->match, JoinAction::Rematch, seat_->seat, seat_->token);
}

Result<std::uint32_t> GameClient::shoot(net::ShotRequest request) {
  if (!seat_) return Result<std::uint32_t>::fail("no seat held");
  request.match = seat_->match;
  request.seat = seat_->seat;
  request.seat_token = seat_->token;
  request.seq = ++last_seq_;
  net::signCommand(request, key());
  const auto sample = net::toWire(request);
  if (auto status = endpoints_->commands.write(*sample); !status) {
    return Result<std::uint32_t>::fail("shot command: " + status.error);
  }
  return Result<std::uint32_t>::ok(request.seq);
}

void GameClient::noteSequence(std::uint32_t seq) {
  last_seq_ = std::max(last_seq_, seq);
}

void GameClient::wait(std::chrono::nanoseconds timeout) const {
  endpoints_->wait(timeout);
}

std::vector<ClientEvent> GameClient::poll() {
  std::vector<ClientEvent> out;
  pollLobby(out);
  pollReplies(out);
  pollStates(out);
  pollResults(out);
  pollFrames(out);
  return out;
}

const MatchView* GameClient::state(const std::string& match) const {
  const auto it = states_.find(match);
  return it == states_.end() ? nullptr : &it->second;
}

void GameClient::pollLobby(std::vector<ClientEvent>& out) {
  for (auto& sample : endpoints_->match_info.takeWithNotices()) {
    if (!sample.meta().valid) {
      if (sample.meta().instance == net::InstanceState::Alive) continue;
      const std::string match(net::textOf(sample->match));
      lobby_.remove(match);
      out.emplace_back(MatchGone{match, sample.meta().instance == net::InstanceState::Disposed});
      continue;
    }
    auto entry = fromWire(*sample);
    if (!entry) {
      problem(entry.error());
      continue;
    }
    lobby_.update(*entry);
    out.emplace_back(std::move(*entry));
  }
}

void GameClient::accept(const JoinAnswer& answer) {
  const auto it = pending_.find(answer.request);
  const JoinAction action = it->second;
  pending_.erase(it);
  if (!answer.accepted()) return;
  if (action == JoinAction::Seat || action == JoinAction::Rejoin) {
    // A new seat starts where the server's results for it left off (a rejoined seat has used
    // numbers, and an earlier process of ours may have used them).
    const bool same = seat_ && seat_->match == answer.match && seat_->seat == answer.seat;
    if (!same) last_seq_ = 0;
    noteSequence(seen_seq_[{answer.match, answer.seat}]);
    seat_ = SeatHolding{answer.match, answer.seat, answer.token};
  } else if (action == JoinAction::Leave && seat_ && seat_->match == answer.match) {
    seat_.reset();
  }
}

void GameClient::pollReplies(std::vector<ClientEvent>& out) {
  for (auto& sample : endpoints_->join_replies.take()) {
    if (net::textOf(sample->client) != options_.client_id) continue;
    auto answer = fromWire(*sample);
    if (!answer) {
      problem(answer.error());
      continue;
    }
    // Replies to requests of an earlier session with the same id, or repeated ones, are stale.
    if (!pending_.count(answer->request)) continue;
    accept(*answer);
    out.emplace_back(std::move(*answer));
  }
}

void GameClient::pollStates(std::vector<ClientEvent>& out) {
  for (auto& sample : endpoints_->states.takeWithNotices()) {
    if (!sample.meta().valid) continue;  // the lobby entry reports a closed match
    auto view = fromWire(*sample);
    if (!view) {
      problem(view.error());
      continue;
    }
    states_[view->match] = *view;
    out.emplace_back(std::move(*view));
  }
}

void GameClient::pollResults(std::vector<ClientEvent>& out) {
  for (auto& sample : endpoints_->results.take()) {
    auto report = fromWire(*sample);
    if (!report) {
      problem(report.error());
      continue;
    }
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
  for (auto& sample : endpoints_->snapshots.take(kSnapshotDepth)) {
    auto frame = fromWire(*sample);
    if (!frame) {
      problem(frame.error());
      continue;
    }
    out.emplace_back(std::move(*frame));
  }
}

}  // namespace pool::client
