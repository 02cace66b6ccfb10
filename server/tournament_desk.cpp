// Running tournaments: entries, matches opened as tables are needed, results taken from the
// matches, every change stored before it is published.
#include "server/tournament_desk.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>

#include "core/hex.h"
#include "core/text.h"
#include "server/store/rating_book.h"
#include "server/store/tournament_book.h"
#include "server/tournament/handicap.h"

namespace pool::server {
namespace {

using nlohmann::json;

tournament::Format formatOf(protocol::TournamentFormat format) {
  switch (format) {
    case protocol::TournamentFormat::SingleElimination:
      return tournament::Format::SingleElimination;
    case protocol::TournamentFormat::DoubleElimination:
      return tournament::Format::DoubleElimination;
    case protocol::TournamentFormat::RoundRobin:
      return tournament::Format::RoundRobin;
  }
  return tournament::Format::SingleElimination;
}

/// A seat token nobody can guess (the seat's commands must carry it).
std::uint64_t freshToken() {
  static std::random_device device;
  std::uint64_t token = 0;
  while (token == 0) token = (static_cast<std::uint64_t>(device()) << 32) | device();
  return token;
}

int stateOf(tournament::MatchState state) {
  switch (state) {
    case tournament::MatchState::Waiting:
      return 0;
    case tournament::MatchState::Ready:
      return 1;
    case tournament::MatchState::InPlay:
      return 2;
    case tournament::MatchState::Done:
      return 3;
  }
  return 0;
}

}  // namespace

TournamentDesk::TournamentDesk(MatchRegistry& registry, store::MatchStore* store)
    : registry_(registry), store_(store) {}

void TournamentDesk::restore() {
  if (!store_) return;
  opened_ = store::tournamentsOpened(store_->database());
  for (const auto& row : store::tournaments(store_->database())) {
    Held held;
    held.id = row.id;
    held.number = row.number;
    held.setup.name = row.name;
    held.setup.format = static_cast<protocol::TournamentFormat>(std::clamp(row.format, 0, 2));
    held.setup.game = rules::gameOfNumber(row.game).value_or(rules::Game::EightBall);
    held.setup.race_to = row.race_to;
    held.setup.capacity = row.capacity;
    held.phase = static_cast<protocol::TournamentPhase>(std::clamp(row.phase, 0, 3));
    // Its options (since schema 10): a field of the wrong kind reads as absent.
    const auto options = json::parse(row.options, nullptr, false);
    const auto field = [&](const char* name) {
      return options.is_object() && options.contains(name) ? options[name] : json();
    };
    held.setup.handicap = field("handicap").is_boolean() && field("handicap").get<bool>();
    if (field("opener").is_string() && field("opened_by").is_string()) {
      const auto opener = bytesFromHex(field("opener").get<std::string>());
      if (opener && opener->size() == protocol::kPublicKeyBytes) {
        held.setup.opened_by = field("opened_by").get<std::string>();
        held.setup.opener_key = *opener;
      }
    }
    if (field("signature").is_string()) {
      held.setup.opening_signature =
          bytesFromHex(field("signature").get<std::string>()).value_or(std::vector<std::uint8_t>{});
    }
    if (!row.state.empty()) {
      auto bracket = tournament::Tournament::fromJson(row.state);
      if (!bracket) {
        spdlog::error("tournament {}: its stored bracket is unreadable ({}): left out", row.id,
                      bracket.error());
        continue;
      }
      held.bracket = std::move(*bracket);
      // The bracket's field is the truth: its entrants' ids are their keys in hex.
      for (const auto& e : held.bracket->entrants()) {
        held.entries.push_back(
            {e.name, bytesFromHex(e.id).value_or(std::vector<std::uint8_t>{}), e.rating, {}});
      }
    } else {
      const auto entries = json::parse(row.entries, nullptr, false);
      for (const auto& e : entries.is_array() ? entries : json::array()) {
        if (!e.is_object() || !e.contains("name") || !e["name"].is_string() || !e.contains("key") ||
            !e["key"].is_string()) {
          continue;
        }
        const auto key = bytesFromHex(e["key"].get<std::string>());
        const double rating =
            e.contains("rating") && e["rating"].is_number() ? e["rating"].get<double>() : 1500.0;
        if (key && key->size() == protocol::kPublicKeyBytes) {
          held.entries.push_back({e["name"].get<std::string>(), *key, rating, {}});
        }
      }
    }
    const auto ids = json::parse(row.match_ids, nullptr, false);
    for (const auto& id : ids.is_array() ? ids : json::array()) {
      held.match_ids.push_back(id.is_string() ? id.get<std::string>() : "");
    }
    if (held.bracket) {
      held.match_ids.resize(held.bracket->matches().size());
      // The tables of its matches in play were resumed: their seats stay the drawn players'.
      for (const auto& m : held.bracket->matches()) {
        if (m.state != tournament::MatchState::InPlay) continue;
        if (Match* table = registry_.find(held.match_ids[static_cast<std::size_t>(m.index)])) {
          table->reserveKeys({held.entries[static_cast<std::size_t>(m.a)].key,
                              held.entries[static_cast<std::size_t>(m.b)].key});
        }
      }
    }
    // The entrants' rating deviations at entry (a bracket keeps the ratings alone).
    const json deviations = field("deviations");
    if (deviations.is_array() && deviations.size() == held.entries.size()) {
      for (std::size_t i = 0; i < held.entries.size(); ++i) {
        if (deviations[i].is_number()) held.entries[i].deviation = deviations[i].get<double>();
      }
    }
    spdlog::info("tournament {} ({}) restored: {}, {} entrants", held.id, held.setup.name,
                 protocol::toString(held.phase), held.entries.size());
    // Those over longest ago make room as the rows are read (kept in the store).
    forgetOldest();
    tournaments_[held.id] = std::move(held);
  }
}

void TournamentDesk::forgetOldest() {
  // The finished and cancelled ones longest ago make room (they stay in the store).
  while (tournaments_.size() >= kMaxTournaments) {
    auto oldest = tournaments_.end();
    for (auto it = tournaments_.begin(); it != tournaments_.end(); ++it) {
      const bool over = it->second.phase == protocol::TournamentPhase::Finished ||
                        it->second.phase == protocol::TournamentPhase::Cancelled;
      if (over && (oldest == tournaments_.end() || it->second.number < oldest->second.number)) {
        oldest = it;
      }
    }
    if (oldest == tournaments_.end()) return;
    tournaments_.erase(oldest);
  }
}

Result<std::string> TournamentDesk::create(const TournamentSetup& setup) {
  using Out = Result<std::string>;
  if (!validPlayerName(setup.name)) return Out::fail("name: 1-31 bytes of UTF-8, no controls");
  if (setup.race_to < 1 || setup.race_to > 15) return Out::fail("race: 1 to 15");
  if (setup.capacity < tournament::kMinEntrants || setup.capacity > tournament::kMaxEntrants) {
    return Out::fail("entrants: 3 to 32");
  }
  // Every match of the bracket crosses the wire: a round robin of N plays N(N-1)/2.
  if (setup.format == protocol::TournamentFormat::RoundRobin &&
      setup.capacity > protocol::kMaxRoundRobinEntrants) {
    return Out::fail("entrants: a round robin takes 3 to " +
                     std::to_string(protocol::kMaxRoundRobinEntrants));
  }
  forgetOldest();
  if (tournaments_.size() >= kMaxTournaments) {
    return Out::fail("this server holds " + std::to_string(kMaxTournaments) +
                     " tournaments not over");
  }
  Held held;
  held.number = ++opened_;
  held.id = registry_.serverId() + "-t" + std::to_string(held.number);
  held.setup = setup;
  save(held);
  spdlog::info("tournament {} ({}) created{}: {}, {}, race to {}, {} entrants{}", held.id,
               escapedForLog(setup.name),
               setup.opened_by.empty() ? "" : " by " + escapedForLog(setup.opened_by),
               protocol::toString(setup.format), rules::toString(setup.game), setup.race_to,
               setup.capacity, setup.handicap ? ", handicapped" : "");
  const std::string id = held.id;
  tournaments_[id] = std::move(held);
  return Out::ok(id);
}

Check<> TournamentDesk::start(const std::string& id) {
  const auto it = tournaments_.find(id);
  if (it == tournaments_.end()) return Check<>::refuse("unknown", "no tournament " + id);
  return startHeld(it->second);
}

Check<> TournamentDesk::startHeld(Held& held) {
  if (held.phase != protocol::TournamentPhase::Entry) {
    return Check<>::refuse("started", held.id + " is " + protocol::toString(held.phase));
  }
  std::vector<tournament::Entrant> field;
  for (const auto& e : held.entries) field.push_back({hexOf(e.key), e.name, e.rating, false});
  auto bracket = tournament::Tournament::create(formatOf(held.setup.format), std::move(field),
                                                {held.setup.race_to});
  if (!bracket) return Check<>::refuse("field", held.id + ": " + bracket.error());
  held.bracket = std::move(*bracket);
  held.match_ids.assign(held.bracket->matches().size(), "");
  held.phase = protocol::TournamentPhase::Running;
  held.changed = true;
  save(held);
  spdlog::info("tournament {} started with {} entrants", held.id, held.entries.size());
  return Check<>::pass();
}

Result<std::vector<std::string>> TournamentDesk::cancel(const std::string& id) {
  using Out = Result<std::vector<std::string>>;
  const auto it = tournaments_.find(id);
  if (it == tournaments_.end()) return Out::fail("no tournament " + id);
  Held& held = it->second;
  if (held.phase == protocol::TournamentPhase::Finished ||
      held.phase == protocol::TournamentPhase::Cancelled) {
    return Out::fail(id + " is " + protocol::toString(held.phase));
  }
  std::vector<std::string> in_play;
  if (held.bracket) {
    auto cancelled = held.bracket->cancel();
    if (!cancelled) return Out::fail(id + ": " + cancelled.error());
    for (const int i : *cancelled) in_play.push_back(held.match_ids[static_cast<std::size_t>(i)]);
  }
  held.phase = protocol::TournamentPhase::Cancelled;
  held.changed = true;
  save(held);
  spdlog::info("tournament {} cancelled; {} match(es) in play go on as ordinary matches", id,
               in_play.size());
  return Out::ok(std::move(in_play));
}

JoinAnswer TournamentDesk::enter(const JoinCommand& c, const std::string& sender) {
  auto refuse = [&](JoinOutcome outcome, std::string why) {
    JoinAnswer answer = JoinAnswer::refuse(outcome, std::move(why));
    answer.match = c.match;
    return answer;
  };
  const bool opening = c.match == protocol::kNewMatch;
  const auto it = tournaments_.find(c.match);
  if (!opening && it == tournaments_.end()) {
    return refuse(JoinOutcome::NoSuchMatch, "no tournament " + c.match);
  }
  if (c.protocol_version != registry_.options().protocol_version) {
    return refuse(JoinOutcome::VersionMismatch,
                  "server speaks protocol " + std::to_string(registry_.options().protocol_version));
  }
  if (!validPlayerName(c.name)) {
    return refuse(JoinOutcome::BadName, "a name is 1-31 bytes of UTF-8 without control characters");
  }
  if (c.public_key.size() != protocol::kPublicKeyBytes || c.signature.empty()) {
    return refuse(JoinOutcome::Unsigned, "an entry is signed by the entrant's key");
  }
  if (protocol::verifySeatRequest(c, c.public_key) != protocol::SignatureCheck::Valid) {
    return refuse(JoinOutcome::BadSignature, "signature: not by the key it carries");
  }
  if (const std::string* why = registry_.banReason(c.public_key)) {
    return refuse(JoinOutcome::NotAllowed, "this key is banned from the server: " + *why);
  }
  return opening ? open(c, sender) : addEntry(it->second, c, sender);
}

JoinAnswer TournamentDesk::open(const JoinCommand& c, const std::string& sender) {
  auto refuse = [&](std::string why) {
    JoinAnswer answer = JoinAnswer::refuse(JoinOutcome::NotAllowed, std::move(why));
    answer.match = c.match;
    return answer;
  };
  if (!c.settings || !c.opening) {
    return refuse("opening a tournament takes its settings (game, race) and its format");
  }
  if (c.settings->practice) return refuse("a tournament is no practice table");
  if (auto ok = protocol::checkSettings(*c.settings); !ok) return refuse(ok.error());
  // The same signed request again (a retry, or someone replaying it) is that tournament.
  for (const auto& [id, held] : tournaments_) {
    if (held.setup.opening_signature == c.signature) {
      return JoinAnswer{JoinOutcome::Accepted, {}, id, -1, 0, c.seq};
    }
  }
  int taking_entries = 0, not_over = 0;
  for (const auto& [id, held] : tournaments_) {
    if (held.setup.opener_key.empty()) continue;
    const bool entry = held.phase == protocol::TournamentPhase::Entry;
    if (!entry && held.phase != protocol::TournamentPhase::Running) continue;
    ++not_over;
    if (!entry) continue;
    ++taking_entries;
    if (held.setup.opener_key == c.public_key || held.opener_sender == sender) {
      return refuse("you opened " + id + ", still taking entries: one at a time");
    }
  }
  if (taking_entries >= kPlayerTournamentsOpen) {
    return refuse("players have " + std::to_string(kPlayerTournamentsOpen) +
                  " tournaments taking entries already");
  }
  if (not_over >= kPlayerTournamentsNotOver) {
    return refuse("players have " + std::to_string(kPlayerTournamentsNotOver) +
                  " tournaments not over already");
  }
  TournamentSetup setup;
  setup.name = c.name + "'s cup";
  if (!validPlayerName(setup.name)) setup.name = c.name;
  setup.format = c.opening->format;
  setup.game = c.settings->game;
  setup.race_to = c.settings->race_to;
  setup.capacity = c.opening->entrants;
  setup.handicap = c.opening->handicap;
  setup.opened_by = c.name;
  setup.opener_key = c.public_key;
  setup.opening_signature = c.signature;
  auto created = create(setup);
  if (!created) return refuse(created.error());
  Held& held = tournaments_.at(*created);
  held.opener_sender = sender;
  JoinAnswer answer = addEntry(held, c, sender);
  answer.match = held.id;
  return answer;
}

JoinAnswer TournamentDesk::addEntry(Held& held, const JoinCommand& c, const std::string& sender) {
  auto refuse = [&](JoinOutcome outcome, std::string why) {
    JoinAnswer answer = JoinAnswer::refuse(outcome, std::move(why));
    answer.match = held.id;
    return answer;
  };
  JoinAnswer accepted{JoinOutcome::Accepted, {}, held.id, -1, 0, c.seq};
  for (const auto& e : held.entries) {
    if (e.key == c.public_key) return accepted;  // entered already: a repeated request
  }
  if (held.phase != protocol::TournamentPhase::Entry) {
    return refuse(JoinOutcome::NotAllowed,
                  held.id + " takes no more entries (" + protocol::toString(held.phase) + ")");
  }
  if (static_cast<int>(held.entries.size()) >= held.setup.capacity) {
    return refuse(JoinOutcome::MatchFull, held.id + " is full");
  }
  const auto from_sender = std::count_if(held.entries.begin(), held.entries.end(),
                                         [&](const Entry& e) { return e.sender == sender; });
  if (from_sender >= kEntriesPerParticipant) {
    return refuse(JoinOutcome::NotAllowed, "at most " + std::to_string(kEntriesPerParticipant) +
                                               " entries from one participant");
  }
  const rating::Rating rated =
      store_ ? store::ratingOf(store_->database(), c.public_key, held.setup.game)
             : rating::Rating{};
  held.entries.push_back({c.name, c.public_key, rated.rating, sender, rated.deviation});
  held.changed = true;
  save(held);
  spdlog::info("tournament {}: {} entered ({} of {})", held.id, escapedForLog(c.name),
               held.entries.size(), held.setup.capacity);
  return accepted;
}

std::array<int, 2> TournamentDesk::spotsOf(const Held& held, int a, int b) const {
  if (!held.setup.handicap || a < 0 || b < 0) return {0, 0};
  const auto& ea = held.entries[static_cast<std::size_t>(a)];
  const auto& eb = held.entries[static_cast<std::size_t>(b)];
  return tournament::handicapSpots({ea.rating, ea.deviation}, {eb.rating, eb.deviation},
                                   held.setup.race_to);
}

void TournamentDesk::step(double now) {
  for (auto& [id, held] : tournaments_) stepHeld(held, now);
}

void TournamentDesk::stepHeld(Held& held, double now) {
  if (held.phase == protocol::TournamentPhase::Entry &&
      static_cast<int>(held.entries.size()) >= held.setup.capacity) {
    if (auto started = startHeld(held); !started) spdlog::error("{}", started.error());
  }
  // A player's tournament takes entries for a while: then it starts with those in, or is off.
  if (held.phase == protocol::TournamentPhase::Entry && !held.setup.opener_key.empty()) {
    if (!held.entry_since) held.entry_since = now;
    if (now - *held.entry_since >= kPlayerEntryWindow) {
      const bool enough = static_cast<int>(held.entries.size()) >= tournament::kMinEntrants;
      if (!enough || !startHeld(held)) {
        spdlog::info("tournament {}: too few entries in {} minutes", held.id,
                     static_cast<int>(kPlayerEntryWindow / 60));
        (void)cancel(held.id);
      }
    }
  }
  if (held.phase != protocol::TournamentPhase::Running || !held.bracket) return;
  tournament::Tournament& bracket = *held.bracket;
  bool changed = false;
  // Results: each match in play whose table is over. (A result can add a match, the grand
  // final's reset: the matches are read by index, and the table ids follow the bracket's size.)
  std::vector<int> in_play;
  for (const auto& m : bracket.matches()) {
    if (m.state == tournament::MatchState::InPlay) in_play.push_back(m.index);
  }
  for (const int index : in_play) {
    const tournament::Match m = bracket.matches()[static_cast<std::size_t>(index)];
    const std::string match_id = held.match_ids[static_cast<std::size_t>(index)];
    const Match* table = match_id.empty() ? nullptr : registry_.find(match_id);
    // A table gone (closed, or abandoned by both players and swept) or left by both: neither
    // player is there to finish it, and both forfeit (the bracket's rule gives such a match to
    // its entrant a, who forfeits the next).
    const bool over = table && !table->closed() && table->phase() == MatchPhase::Over;
    const bool abandoned = !over && (!table || table->closed() ||
                                     (!table->seats()[0].taken() && !table->seats()[1].taken()));
    if (abandoned) {
      spdlog::warn("tournament {}: {} ({}) has no players left: both forfeit", held.id,
                   match_id.empty() ? "a match" : match_id, m.round);
      for (const int entrant : {m.a, m.b}) {
        if (bracket.finished() || bracket.withdrawn(entrant)) continue;
        if (auto decided = bracket.forfeit(entrant); !decided) {
          spdlog::error("tournament {}: forfeit: {}", held.id, decided.error());
        }
      }
      held.match_ids.resize(bracket.matches().size());
      changed = true;
      continue;
    }
    if (!over) continue;
    const int seat = table->game().winner;
    if (seat != 0 && seat != 1) continue;
    const int winner = seat == 0 ? m.a : m.b;
    const int loser = seat == 0 ? m.b : m.a;
    const auto& seats = table->seats();
    // A match forfeited by one who left (or never came): that player forfeits the tournament's
    // later matches too. A match played out (or a rack conceded by a player at the table) is a
    // result, whoever is away now (a restart leaves everyone away until they come back).
    // (The seat of one forfeited for not coming back is away, or already free again.)
    const bool walked_out = table->game().end == rules::GameEnd::Forfeit &&
                            !seats[static_cast<std::size_t>(1 - seat)].connected();
    auto reported = walked_out
                        ? Check<>::refuse("forfeit", "walked out")
                        : bracket.report(m.index, winner, seats[0].racks_won, seats[1].racks_won);
    if (!reported) {
      if (!walked_out) {
        spdlog::warn("tournament {}: result of {}: {}; decided by forfeit", held.id, match_id,
                     reported.error());
      }
      auto decided = bracket.forfeit(loser);
      if (!decided) {
        spdlog::error("tournament {}: forfeit: {}", held.id, decided.error());
        continue;
      }
    }
    spdlog::info("tournament {}: {} ({}) won by {}", held.id, match_id, m.round,
                 escapedForLog(bracket.entrants()[static_cast<std::size_t>(winner)].name));
    held.match_ids.resize(bracket.matches().size());
    changed = true;
  }
  // Matches ready to play: a table each, the drawn players' seats reserved for their keys.
  for (const int i : bracket.readyMatches()) {
    const auto& m = bracket.matches()[static_cast<std::size_t>(i)];
    const auto& a = held.entries[static_cast<std::size_t>(m.a)];
    const auto& b = held.entries[static_cast<std::size_t>(m.b)];
    std::string name = held.setup.name + " " + m.round;
    if (name.size() > 40) name.resize(40);
    Match* table = registry_.open(name);
    if (!table) break;  // the server is full: the next pass tries again
    protocol::MatchSettings settings;
    settings.game = held.setup.game;
    settings.race_to = held.setup.race_to;
    if (auto reserved =
            table->reserveSeats({a.name, b.name}, {a.key, b.key}, {freshToken(), freshToken()},
                                settings, now, spotsOf(held, m.a, m.b));
        !reserved) {
      spdlog::error("tournament {}: {}: {}", held.id, table->id(), reserved.error());
      registry_.closeMatch(table->id(), "the tournament could not seat its players");
      break;
    }
    if (auto started = bracket.start(i); !started) {
      spdlog::error("tournament {}: start {}: {}", held.id, i, started.error());
      continue;
    }
    held.match_ids[static_cast<std::size_t>(i)] = table->id();
    spdlog::info("tournament {}: {} {} v {} at {}", held.id, m.round, escapedForLog(a.name),
                 escapedForLog(b.name), table->id());
    changed = true;
  }
  if (bracket.finished()) {
    held.phase = protocol::TournamentPhase::Finished;
    spdlog::info(
        "tournament {} won by {}", held.id,
        escapedForLog(bracket.entrants()[static_cast<std::size_t>(*bracket.champion())].name));
    changed = true;
  }
  if (changed) {
    held.changed = true;
    save(held);
  }
}

protocol::TournamentView TournamentDesk::viewOf(const Held& held) const {
  protocol::TournamentView v;
  v.tournament = held.id;
  v.server = registry_.serverId();
  v.name = held.setup.name;
  v.format = held.setup.format;
  v.game = held.setup.game;
  v.race_to = held.setup.race_to;
  v.phase = held.phase;
  v.capacity = held.setup.capacity;
  v.handicap = held.setup.handicap;
  v.opened_by = held.setup.opened_by;
  for (std::size_t i = 0; i < held.entries.size(); ++i) {
    const auto& e = held.entries[i];
    protocol::TournamentEntrantView ev;
    ev.name = e.name;
    ev.player = hexOf(e.key);
    ev.rating = static_cast<int>(std::lround(e.rating));
    if (held.bracket) {
      ev.seed = held.bracket->seed(static_cast<int>(i));
      ev.withdrawn = held.bracket->withdrawn(static_cast<int>(i));
    }
    v.entrants.push_back(std::move(ev));
  }
  if (held.bracket) {
    for (const auto& s : held.bracket->standings()) {
      v.entrants[static_cast<std::size_t>(s.entrant)].place = s.place;
    }
    for (const auto& m : held.bracket->matches()) {
      const auto spots = spotsOf(held, m.a, m.b);
      v.matches.push_back({m.round, m.a, m.b, stateOf(m.state), m.winner, m.racksA, m.racksB,
                           m.forfeit, held.match_ids[static_cast<std::size_t>(m.index)], spots[0],
                           spots[1]});
    }
    v.champion = held.bracket->champion().value_or(-1);
  }
  return v;
}

std::vector<protocol::TournamentView> TournamentDesk::views() const {
  std::vector<protocol::TournamentView> out;
  for (const auto& [id, held] : tournaments_) out.push_back(viewOf(held));
  return out;
}

std::vector<protocol::TournamentView> TournamentDesk::takeChanged() {
  std::vector<protocol::TournamentView> out;
  for (auto& [id, held] : tournaments_) {
    if (!held.changed) continue;
    held.changed = false;
    out.push_back(viewOf(held));
  }
  return out;
}

void TournamentDesk::save(const Held& held) {
  if (!store_) return;
  json entries = json::array();
  for (const auto& e : held.entries) {
    entries.push_back({{"name", e.name}, {"key", hexOf(e.key)}, {"rating", e.rating}});
  }
  store::StoredTournament row;
  row.id = held.id;
  row.number = held.number;
  row.name = held.setup.name;
  row.format = static_cast<int>(held.setup.format);
  row.game = rules::gameNumber(held.setup.game);
  row.race_to = held.setup.race_to;
  row.capacity = held.setup.capacity;
  row.phase = static_cast<int>(held.phase);
  row.entries = entries.dump(-1, ' ', false, json::error_handler_t::replace);
  row.state = held.bracket ? held.bracket->toJson() : std::string();
  row.match_ids = json(held.match_ids).dump();
  json options = {{"handicap", held.setup.handicap}};
  if (!held.setup.opener_key.empty()) {
    options["opened_by"] = held.setup.opened_by;
    options["opener"] = hexOf(held.setup.opener_key);
    options["signature"] = hexOf(held.setup.opening_signature);
  }
  json deviations = json::array();
  for (const auto& e : held.entries) deviations.push_back(e.deviation);
  options["deviations"] = deviations;
  row.options = options.dump(-1, ' ', false, json::error_handler_t::replace);
  store::saveTournament(store_->database(), row);
  store_->checkStillThere();
}

}  // namespace pool::server
