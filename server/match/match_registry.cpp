// The lobby's bookkeeping: opening and finding matches, routing joins and commands, presence.
#include "match/match_registry.h"

#include <algorithm>
#include <cstdlib>

#include "net/key_pair.h"

namespace pool::server {

namespace {

std::uint64_t seedOf(std::uint64_t seed) {
  return seed != 0 ? seed : randomSeed();
}

JoinAnswer about(JoinAnswer answer, const std::string& match) {
  if (answer.match.empty()) answer.match = match;
  return answer;
}

}  // namespace

bool validPlayerName(std::string_view name) {
  return !name.empty() && name.size() <= 31 &&
         std::all_of(name.begin(), name.end(), [](char c) { return c >= ' ' && c != 127; });
}

MatchRegistry::MatchRegistry(RegistryOptions options, std::shared_ptr<const TableKit> kit)
    : options_(std::move(options)),
      random_(seedOf(options_.seed)),
      server_id_(options_.server_id.empty() ? randomHex(random_) : options_.server_id),
      runner_(std::make_shared<ShotRunner>(std::move(kit))) {}

Match* MatchRegistry::open(std::string name, std::optional<std::uint64_t> rack_seed) {
  if (matches_.size() >= options_.max_matches) return nullptr;
  ++opened_;
  if (name.empty()) name = "Table " + std::to_string(opened_);
  const std::string id = server_id_ + "-" + std::to_string(opened_);
  matches_.push_back(std::make_unique<Match>(id, std::move(name), runner_, options_.match,
                                             rack_seed ? *rack_seed : random_.next()));
  return matches_.back().get();
}

Match* MatchRegistry::adopt(const MatchSnapshot& snapshot, double now) {
  if (matches_.size() >= options_.max_matches || find(snapshot.id)) return nullptr;
  continueAfter(snapshot.number);
  matches_.push_back(std::make_unique<Match>(snapshot, runner_, options_.match, now));
  if (snapshot.client_made) client_made_.insert(snapshot.id);
  return matches_.back().get();
}

MatchSnapshot MatchRegistry::snapshotOf(const Match& match) const {
  MatchSnapshot out = match.snapshot();
  // Ids are "<server id>-<n>": the number is what follows the last dash.
  const auto dash = out.id.rfind('-');
  if (dash != std::string::npos) out.number = std::strtoull(out.id.c_str() + dash + 1, nullptr, 10);
  out.client_made = client_made_.count(out.id) > 0;
  return out;
}

Match* MatchRegistry::find(std::string_view id) {
  for (auto& m : matches_) {
    if (m->id() == id && !m->closed()) return m.get();
  }
  return nullptr;
}

std::vector<Match*> MatchRegistry::matches() {
  std::vector<Match*> out;
  for (auto& m : matches_) out.push_back(m.get());
  return out;
}

JoinAnswer MatchRegistry::join(const JoinCommand& c) {
  if (c.protocol_version != options_.protocol_version) {
    return about(
        JoinAnswer::refuse(JoinOutcome::VersionMismatch,
                           "server speaks protocol " + std::to_string(options_.protocol_version)),
        c.match);
  }
  if (c.action == JoinAction::Seat) return about(seat(c), c.match);
  Match* match = find(c.match);
  if (!match) {
    return about(JoinAnswer::refuse(JoinOutcome::NoSuchMatch, "no match " + c.match), c.match);
  }
  switch (c.action) {
    case JoinAction::Spectate:
      return match->addSpectator(c.client);
    case JoinAction::Rejoin:
      return about(match->rejoin(c.token, c.client, c.public_key), c.match);
    case JoinAction::Leave:
      return about(leave(c), c.match);
    case JoinAction::Rematch:
      return about(match->rematch(c.token), c.match);
    case JoinAction::Seat:
      break;
  }
  return about(JoinAnswer::refuse(JoinOutcome::NotAllowed, "unknown action"), c.match);
}

JoinAnswer MatchRegistry::seat(const JoinCommand& c) {
  if (!validPlayerName(c.name)) {
    return JoinAnswer::refuse(JoinOutcome::BadName, "a name is 1-31 printable characters");
  }
  if (c.seat < -1 || c.seat > 1) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed, "seat: must be 0, 1 or -1 (any)");
  }
  if (c.public_key.size() != net::kPublicKeyBytes) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed,
                              "public_key: a seat needs the 32-byte Ed25519 key of its commands");
  }
  Match* match = nullptr;
  if (c.match == kNewMatch) {
    match = open();
    if (!match) return JoinAnswer::refuse(JoinOutcome::ServerFull, "no room for another match");
    client_made_.insert(match->id());
  } else {
    match = find(c.match);
    if (!match) return JoinAnswer::refuse(JoinOutcome::NoSuchMatch, "no match " + c.match);
  }
  return match->takeSeat(c.seat, c.name, c.client, random_.token(), c.public_key);
}

JoinAnswer MatchRegistry::leave(const JoinCommand& c) {
  Match* match = find(c.match);
  if (c.token != 0) return match->leave(c.token);
  if (!match->removeSpectator(c.client)) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed, "not watching " + c.match);
  }
  return {JoinOutcome::Accepted, {}, c.match, -1, 0};
}

CommandAnswer MatchRegistry::shoot(const net::ShotRequest& command, double now) {
  Match* match = find(command.match);
  if (match) return match->handleShot(command, now);
  CommandAnswer answer;
  answer.seat = command.seat;
  answer.seq = command.seq;
  answer.rejection = {Reject::NoSuchMatch, "no match " + command.match};
  return answer;
}

void MatchRegistry::clientGone(const std::string& client, double now) {
  for (auto& m : matches_) m->clientGone(client, now);
}

void MatchRegistry::expireAway(double now, double grace) {
  for (auto& m : matches_) {
    while (m->expireAway(now, grace)) {
    }
  }
}

std::vector<std::string> MatchRegistry::sweepEmpty() {
  std::vector<std::string> closed;
  for (auto& m : matches_) {
    if (client_made_.count(m->id()) && m->empty() && !m->inMotion()) {
      m->close();
      closed.push_back(m->id());
      client_made_.erase(m->id());
    }
  }
  std::erase_if(matches_, [](const auto& m) { return m->closed(); });
  return closed;
}

std::optional<double> MatchRegistry::nextFrameDue() const {
  std::optional<double> next;
  for (const auto& m : matches_) {
    const auto due = m->nextFrameDue();
    if (due && (!next || *due < *next)) next = due;
  }
  return next;
}

}  // namespace pool::server
