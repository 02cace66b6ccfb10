// The lobby's bookkeeping: opening and finding matches, routing joins and commands, presence.
#include "server/match/match_registry.h"

#include <algorithm>
#include <cstdlib>

#include "core/text.h"
#include "protocol/key_pair.h"

namespace pool::server {

namespace {

std::uint64_t seedOf(std::uint64_t seed) {
  return seed != 0 ? seed : randomSeed();
}

/// Keys whose last sequence number is remembered before the unseated ones are forgotten.
constexpr std::size_t kMaxKeyFloors = 100000;

JoinAnswer about(JoinAnswer answer, const std::string& match) {
  if (answer.match.empty()) answer.match = match;
  return answer;
}

}  // namespace

bool validPlayerName(std::string_view name) {
  return isCleanUtf8(name, 31);
}

MatchRegistry::MatchRegistry(RegistryOptions options, std::shared_ptr<const game::LoadedTable> kit)
    : options_(std::move(options)),
      random_(seedOf(options_.seed)),
      server_id_(options_.server_id.empty() ? randomHex(random_) : options_.server_id),
      runner_(std::make_shared<ShotRunner>(std::move(kit))) {
  // Every match of this registry finds its game's table here (three-cushion's carom table).
  if (!options_.match.tables) options_.match.tables = std::make_shared<TableRunners>(runner_);
}

Match* MatchRegistry::open(std::string name, std::optional<std::uint64_t> rack_seed,
                           table::RackGenerator generator) {
  if (matches_.size() >= options_.max_matches) return nullptr;
  ++opened_;
  if (name.empty()) name = "Table " + std::to_string(opened_);
  const std::string id = server_id_ + "-" + std::to_string(opened_);
  matches_.push_back(std::make_unique<Match>(id, std::move(name), runner_, options_.match,
                                             rack_seed            ? *rack_seed
                                             : options_.rack_seed ? options_.rack_seed + opened_
                                                                  : random_.next(),
                                             generator));
  return matches_.back().get();
}

Match* MatchRegistry::adopt(const MatchSnapshot& snapshot, double now) {
  if (matches_.size() >= options_.max_matches || find(snapshot.id)) return nullptr;
  continueAfter(snapshot.number);
  matches_.push_back(std::make_unique<Match>(snapshot, runner_, options_.match, now));
  if (snapshot.client_made) client_made_.insert(snapshot.id);
  for (const Seat& s : snapshot.seats) {
    if (s.taken()) useKeySeq(s.public_key, s.last_seq);
  }
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
  if (c.action == JoinAction::Spectate) return match->addSpectator(c.client);
  if (!protocol::changesSeat(c)) return about(leave(c), c.match);  // a spectator's leave
  if (c.action != JoinAction::Leave) {
    if (auto refusal = bannedSeat(c)) return about(std::move(*refusal), c.match);
  }
  JoinAnswer answer = match->seatRequest(c);
  if (answer.outcome != JoinOutcome::StaleSequence && answer.last_seq != 0) {
    useKeySeq(c.public_key, answer.last_seq);  // the key's signature checked out
  }
  return about(std::move(answer), c.match);
}

JoinAnswer MatchRegistry::seat(const JoinCommand& c) {
  if (!validPlayerName(c.name)) {
    return JoinAnswer::refuse(JoinOutcome::BadName,
                              "a name is 1-31 bytes of UTF-8 without control characters");
  }
  if (c.seat < -1 || c.seat > 1) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed, "seat: must be 0, 1 or -1 (any)");
  }
  if (c.public_key.size() != protocol::kPublicKeyBytes) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed,
                              "public_key: a seat needs the 32-byte Ed25519 key of its commands");
  }
  if (auto refusal = bannedSeat(c)) return std::move(*refusal);
  if (c.signature.empty()) {
    return JoinAnswer::refuse(JoinOutcome::Unsigned, "signature: seat requests must be signed");
  }
  if (const std::uint32_t floor = keyFloor(c.public_key); c.seq <= floor) {
    JoinAnswer stale =
        JoinAnswer::refuse(JoinOutcome::StaleSequence, "seq " + std::to_string(c.seq) +
                                                           " is not above the key's last used " +
                                                           std::to_string(floor));
    stale.last_seq = floor;
    return stale;
  }
  if (protocol::verifySeatRequest(c, c.public_key) != protocol::SignatureCheck::Valid) {
    return JoinAnswer::refuse(JoinOutcome::BadSignature, "signature: not by the key it carries");
  }
  if (c.settings) {
    if (auto why = protocol::checkSettings(*c.settings); !why) {
      return JoinAnswer::refuse(JoinOutcome::NotAllowed, "settings: " + why.error());
    }
  }
  useKeySeq(c.public_key, c.seq);
  Match* match = nullptr;
  if (c.match == kNewMatch) {
    match = open();
    if (!match) return JoinAnswer::refuse(JoinOutcome::ServerFull, "no room for another match");
    client_made_.insert(match->id());
  } else {
    match = find(c.match);
    if (!match) return JoinAnswer::refuse(JoinOutcome::NoSuchMatch, "no match " + c.match);
  }
  JoinAnswer answer =
      match->takeSeat(c.seat, c.name, c.client, random_.token(), c.public_key, c.settings);
  answer.last_seq = c.seq;
  return answer;
}

std::optional<JoinAnswer> MatchRegistry::bannedSeat(const JoinCommand& c) const {
  const std::string* why = banReason(c.public_key);
  if (!why) return std::nullopt;
  return JoinAnswer::refuse(JoinOutcome::NotAllowed, "this key is banned from the server: " + *why);
}

JoinAnswer MatchRegistry::leave(const JoinCommand& c) {
  Match* match = find(c.match);
  if (!match->removeSpectator(c.client)) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed, "not watching " + c.match);
  }
  return {JoinOutcome::Accepted, {}, c.match, -1, 0, 0};
}

std::uint32_t MatchRegistry::keyFloor(const std::vector<std::uint8_t>& key) const {
  const auto it = key_seq_.find(key);
  return it == key_seq_.end() ? 0 : it->second;
}

void MatchRegistry::useKeySeq(const std::vector<std::uint8_t>& key, std::uint32_t seq) {
  if (key.size() != protocol::kPublicKeyBytes) return;
  auto& floor = key_seq_[key];
  floor = std::max(floor, seq);
  if (key_seq_.size() <= kMaxKeyFloors) return;
  // Bounded memory: keep the keys bound to a seat (a request replayed for a key forgotten here
  // still needs that key's signature, and seats it only where a seat is free).
  std::set<std::vector<std::uint8_t>> seated;
  for (const auto& m : matches_) {
    for (const Seat& s : m->seats()) {
      if (s.taken()) seated.insert(s.public_key);
    }
  }
  std::erase_if(key_seq_, [&](const auto& entry) { return !seated.count(entry.first); });
}

namespace {

// A banned key's seat, checked before the signature: nothing is used up, nothing changes.
template <class Command>
std::optional<CommandAnswer> bannedCommand(const MatchRegistry& registry, Match* match,
                                           const Command& command) {
  if (!match || (command.seat != 0 && command.seat != 1)) return std::nullopt;
  const Seat& seat = match->seats()[static_cast<std::size_t>(command.seat)];
  const std::string* why = seat.taken() ? registry.banReason(seat.public_key) : nullptr;
  if (!why) return std::nullopt;
  CommandAnswer answer;
  answer.seat = command.seat;
  answer.seq = command.seq;
  answer.rejection = {Reject::MatchOver, "seat " + std::to_string(command.seat) +
                                             "'s key is banned from the server: " + *why};
  return answer;
}

}  // namespace

CommandAnswer MatchRegistry::shoot(const protocol::ShotRequest& command, double now) {
  return route(command, [&](Match& match) { return match.handleShot(command, now); });
}

CommandAnswer MatchRegistry::practice(const protocol::PracticeRequest& command, double now) {
  return route(command, [&](Match& match) { return match.handlePractice(command, now); });
}

template <class Command, class Handle>
CommandAnswer MatchRegistry::route(const Command& command, Handle&& handle) {
  Match* match = find(command.match);
  if (auto banned = bannedCommand(*this, match, command)) return *banned;
  if (match) {
    CommandAnswer answer = handle(*match);
    if (command.seat == 0 || command.seat == 1) {
      const Seat& seat = match->seats()[static_cast<std::size_t>(command.seat)];
      if (seat.taken()) useKeySeq(seat.public_key, seat.last_seq);
    }
    return answer;
  }
  CommandAnswer answer;
  answer.seat = command.seat;
  answer.seq = command.seq;
  answer.rejection = {Reject::NoSuchMatch, "no match " + command.match};
  return answer;
}

bool MatchRegistry::clientGone(const std::string& client, double now) {
  bool seated = false;
  for (auto& m : matches_) seated = m->clientGone(client, now) || seated;
  return seated;
}

bool MatchRegistry::seats(const std::string& client) const {
  return std::any_of(matches_.begin(), matches_.end(),
                     [&](const auto& m) { return m->seats(client); });
}

std::size_t MatchRegistry::spectators() const {
  std::size_t n = 0;
  for (const auto& m : matches_) n += m->spectators();
  return n;
}

void MatchRegistry::pause(double seconds) {
  for (auto& m : matches_) m->pause(seconds);
}

std::vector<std::pair<std::string, CommandAnswer>> MatchRegistry::tickClocks(double now) {
  std::vector<std::pair<std::string, CommandAnswer>> judged;
  for (auto& m : matches_) {
    if (auto answer = m->tickClock(now)) judged.emplace_back(m->id(), std::move(*answer));
  }
  return judged;
}

void MatchRegistry::expireAway(double now, double grace) {
  for (auto& m : matches_) {
    while (m->expireAway(now, grace)) {
    }
  }
}

bool MatchRegistry::closeMatch(std::string_view id, const std::string& why) {
  Match* match = find(id);
  if (!match) return false;
  match->close(why);
  client_made_.erase(match->id());
  return true;
}

void MatchRegistry::ban(const std::vector<std::uint8_t>& key, const std::string& reason) {
  banned_.emplace(key, reason);
}

bool MatchRegistry::unban(const std::vector<std::uint8_t>& key) {
  return banned_.erase(key) > 0;
}

const std::string* MatchRegistry::banReason(const std::vector<std::uint8_t>& key) const {
  const auto it = banned_.find(key);
  return it == banned_.end() ? nullptr : &it->second;
}

std::vector<std::string> MatchRegistry::sweepEmpty() {
  std::vector<std::string> closed;
  for (auto& m : matches_) {
    if (m->closed()) {
      closed.push_back(m->id());  // closed by closeMatch
      continue;
    }
    // A game in play that both players abandoned closes too (see Match::expireAway).
    const bool closes =
        client_made_.count(m->id()) || m->phase() == MatchPhase::Over || m->inPlay();
    if (closes && m->empty() && !m->inMotion()) {
      m->close();
      closed.push_back(m->id());
      client_made_.erase(m->id());
    }
  }
  std::erase_if(matches_, [](const auto& m) { return m->closed(); });
  return closed;
}

int MatchRegistry::keepFreeTables(int count) {
  int free = 0;
  for (const auto& m : matches_) {
    if (!m->closed() && m->phase() == MatchPhase::Lobby && !m->seats()[0].taken() &&
        !m->seats()[1].taken()) {
      ++free;
    }
  }
  int opened = 0;
  for (; free < count; ++free, ++opened) {
    if (!open()) break;  // the server is full
  }
  return opened;
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
