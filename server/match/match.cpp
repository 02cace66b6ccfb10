// A match's seats, its shots from command to committed verdict, and the frames in between.
#include "server/match/match.h"

#include <algorithm>

#include "game/rack_layout.h"
#include "rules/eight_ball.h"
#include "rules/game_rules.h"
#include "rules/practice.h"
#include "rules/shot.h"
#include "server/match/command_check.h"

namespace pool::server {

namespace {

JoinAnswer seated(const std::string& match, int seat, std::uint64_t token) {
  return {JoinOutcome::Accepted, {}, match, seat, token};
}

// The frames to publish: every trajectory sample, then the table at rest when the shot ended.
std::vector<physics::Sample> framesOf(physics::ShotOutcome& outcome) {
  std::vector<physics::Sample> frames = std::move(outcome.trajectory);
  const double last = frames.empty() ? 0.0 : frames.back().t;
  frames.push_back(physics::Sample{std::max(last, outcome.t_rest.value_or(last)), outcome.balls});
  return frames;
}

std::vector<double> timesOf(const std::vector<physics::Sample>& frames) {
  std::vector<double> times;
  times.reserve(frames.size());
  for (const auto& f : frames) times.push_back(f.t);
  return times;
}

}  // namespace

Match::Match(std::string id, std::string name, std::shared_ptr<ShotRunner> runner,
             MatchOptions options, std::uint64_t rack_seed, table::RackGenerator generator)
    : id_(std::move(id)),
      name_(std::move(name)),
      runner_(std::move(runner)),
      options_(options),
      rack_seed_(rack_seed),
      rack_generator_(generator),
      settings_(options.settings) {
  if (auto own = runnerFor(settings_.game)) runner_ = *own;
  balls_ = layout(layouts_++, settings_.game);
}

Match::Match(const MatchSnapshot& snapshot, std::shared_ptr<ShotRunner> runner,
             MatchOptions options, double now)
    : id_(snapshot.id),
      name_(snapshot.name),
      runner_(std::move(runner)),
      options_(options),
      rack_seed_(snapshot.rack_seed),
      layouts_(snapshot.layouts),
      rack_generator_(snapshot.rack_generator),
      seats_(snapshot.seats),
      started_(snapshot.started),
      closed_(snapshot.closed),
      game_(snapshot.game),
      balls_(snapshot.balls),
      shot_number_(snapshot.shot_number),
      rack_(snapshot.rack),
      last_verdict_(snapshot.last_verdict),
      // Past every revision published before the restart, so readers take the new states.
      revision_(snapshot.revision + 1),
      settings_(snapshot.settings) {
  if (auto own = runnerFor(settings_.game)) {
    runner_ = *own;
  } else if (!closed_) {
    // Its game's table cannot load here: the match is not resumed on another table.
    close("closed: its table cannot load: " + own.error());
  }
  for (Seat& s : seats_) {
    if (s.taken()) s.away_since = now;
  }
  // A resumed rack's clock starts afresh, each player with an extension.
  if (settings_.clockOn() && inPlay()) {
    extensions_ = {1, 1};
    restartClock(0.0);
  }
}

// ---- Seats --------------------------------------------------------------------------------------

pool::Check<> Match::reserveSeats(const std::array<std::string, 2>& players,
                                  const std::array<std::vector<std::uint8_t>, 2>& keys,
                                  const std::array<std::uint64_t, 2>& tokens,
                                  const protocol::MatchSettings& settings, double now,
                                  const std::array<int, 2>& spots) {
  if (started_ || seats_[0].taken() || seats_[1].taken()) {
    return pool::Check<>::refuse("taken", "the table has started or a seat is taken");
  }
  for (const int spot : spots) {
    if (spot < 0 || spot >= settings.race_to) {
      return pool::Check<>::refuse("spot", "a spot is 0 to one below the race");
    }
  }
  if (settings != settings_) {
    auto runner = runnerFor(settings.game);
    if (!runner) {
      return pool::Check<>::refuse("game", std::string("this server cannot play ") +
                                               rules::toString(settings.game) + ": " +
                                               runner.error());
    }
    runner_ = *runner;
    settings_ = settings;
    balls_ = layout(layouts_ - 1, settings_.game);
  }
  for (std::size_t s = 0; s < 2; ++s) {
    Seat& seat = seats_[s];
    seat = Seat{};
    seat.player = players[s];
    seat.token = tokens[s];
    seat.public_key = keys[s];
    seat.away_since = now;
    seat.racks_won = spots[s];  // on the wire from the start
  }
  reserveKeys(keys);
  touch();
  startRack(0);
  return pool::Check<>::pass();
}

JoinAnswer Match::takeSeat(int seat, const std::string& player, const std::string& client,
                           std::uint64_t token, const std::vector<std::uint8_t>& public_key,
                           const std::optional<protocol::MatchSettings>& settings) {
  for (int s = 0; s < 2; ++s) {
    const Seat& mine = seats_[static_cast<std::size_t>(s)];
    if (mine.taken() && mine.client == client && mine.public_key == public_key &&
        (seat == s || seat == -1)) {
      return seated(id_, s, mine.token);  // a repeated request: same seat, same token
    }
  }
  // A seat bound to this key whose player is away is theirs again (the key signed the request).
  for (int s = 0; s < 2; ++s) {
    Seat& mine = seats_[static_cast<std::size_t>(s)];
    if (mine.taken() && mine.away_since && mine.public_key == public_key &&
        (seat == s || seat == -1)) {
      mine.client = client;
      mine.away_since.reset();
      touch();
      return seated(id_, s, mine.token);
    }
  }
  if (reserved()) {
    // A tournament's table: a seat is its drawn player's alone.
    const int mine = reserved_[0] == public_key ? 0 : (reserved_[1] == public_key ? 1 : -1);
    if (mine < 0 || (seat != -1 && seat != mine)) {
      return JoinAnswer::refuse(JoinOutcome::SeatTaken,
                                "this table's seats are kept for a tournament's drawn players");
    }
    seat = mine;
  }
  if (flight_) return JoinAnswer::refuse(JoinOutcome::NotAllowed, "a shot is in motion");
  if (seat == -1) {
    seat = !seats_[0].taken() ? 0 : (!seats_[1].taken() ? 1 : -1);
    if (seat == -1) return JoinAnswer::refuse(JoinOutcome::MatchFull, "both seats are taken");
  }
  Seat& s = seats_[static_cast<std::size_t>(seat)];
  if (s.taken()) {
    return JoinAnswer::refuse(JoinOutcome::SeatTaken, "seat " + std::to_string(seat) + " is taken");
  }
  s = Seat{};
  s.player = player;
  s.client = client;
  s.token = token;
  s.public_key = public_key;
  // The first player at a table that has not started sets how it is played.
  const bool opens = !started_ && !seats_[static_cast<std::size_t>(1 - seat)].taken();
  if (opens && settings && *settings != settings_) {
    // A game with a table of its own (three-cushion) moves the match onto that table.
    auto runner = runnerFor(settings->game);
    if (!runner) {
      s = Seat{};
      return JoinAnswer::refuse(JoinOutcome::NotAllowed, std::string("this server cannot play ") +
                                                             rules::toString(settings->game) +
                                                             ": " + runner.error());
    }
    runner_ = *runner;
    settings_ = *settings;
    // The same layout number again: the racks of a match do not depend on who chose what.
    balls_ = layout(layouts_ - 1, settings_.game);
  }
  touch();
  if (practice() && !started_) startPractice();
  // (A tournament's decided race starts no new rack.)
  if (seats_[0].taken() && seats_[1].taken() && !inPlay() &&
      !(reserved() && phase() == MatchPhase::Over)) {
    startRack(rack_ % 2 == 0 ? 0 : 1);
  }
  return seated(id_, seat, token);
}

JoinAnswer Match::seatRequest(const protocol::SeatRequest& r) {
  const auto found = seatOf(r);
  if (!found) return JoinAnswer::refuse(JoinOutcome::BadToken, "no seat here is bound to that key");
  const int seat = *found;
  Seat& s = seats_[static_cast<std::size_t>(seat)];
  const std::string which = "seat " + std::to_string(seat);
  if (r.token != s.token) {
    return JoinAnswer::refuse(JoinOutcome::BadToken, "the token is not " + which + "'s");
  }
  if (r.signature.empty()) {
    return JoinAnswer::refuse(JoinOutcome::Unsigned, "signature: seat requests must be signed");
  }
  if (r.seq <= s.last_seq) {
    JoinAnswer stale =
        JoinAnswer::refuse(JoinOutcome::StaleSequence, "seq " + std::to_string(r.seq) +
                                                           " is not above the last used " +
                                                           std::to_string(s.last_seq));
    stale.last_seq = s.last_seq;
    return stale;
  }
  if (protocol::verifySeatRequest(r, s.public_key) != protocol::SignatureCheck::Valid) {
    return JoinAnswer::refuse(JoinOutcome::BadSignature, "signature: not " + which + "'s key");
  }
  s.last_seq = r.seq;  // used up from here on, whatever the outcome
  touch();
  JoinAnswer answer = JoinAnswer::refuse(JoinOutcome::NotAllowed, "not a seat request");
  switch (r.action) {
    case JoinAction::Rejoin:
      answer = rejoinSeat(seat, r.client);
      break;
    case JoinAction::Leave:
      answer = leaveSeat(seat);
      break;
    case JoinAction::Rematch:
      answer = rematchSeat(seat);
      break;
    case JoinAction::Concede:
      answer = concedeSeat(seat);
      break;
    case JoinAction::Seat:
    case JoinAction::Spectate:
    case JoinAction::Enter:
      break;
  }
  answer.last_seq = r.seq;
  return answer;
}

JoinAnswer Match::rejoinSeat(int seat, const std::string& client) {
  Seat& s = seats_[static_cast<std::size_t>(seat)];
  s.client = client;
  s.away_since.reset();
  touch();
  return seated(id_, seat, s.token);
}

JoinAnswer Match::leaveSeat(int seat) {
  if (inPlay() && !practice()) forfeitSeat(seat, "left");
  seats_[static_cast<std::size_t>(seat)] = Seat{};
  touch();
  return seated(id_, seat, 0);
}

JoinAnswer Match::rematchSeat(int seat) {
  if (reserved()) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed, "a tournament's match has no rematch");
  }
  if (phase() != MatchPhase::Over || pending_forfeit_) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed, "the match is not over");
  }
  seats_[static_cast<std::size_t>(seat)].wants_rematch = true;
  touch();
  if (seats_[0].taken() && seats_[1].taken() && seats_[0].wants_rematch &&
      seats_[1].wants_rematch) {
    // A new race: the score starts again; the breaks go on as the settings say.
    for (Seat& s : seats_) s.racks_won = 0;
    startRack(nextBreaker(game_.winner >= 0 ? game_.winner : rules::opponentOf(game_.breaker)));
  }
  return seated(id_, seat, seats_[static_cast<std::size_t>(seat)].token);
}

JoinAnswer Match::concedeSeat(int seat) {
  if (practice())
    return JoinAnswer::refuse(JoinOutcome::NotAllowed, "a practice table has no rack to concede");
  if (!inPlay() || pending_forfeit_) {
    return JoinAnswer::refuse(JoinOutcome::NotAllowed, "no rack is in play");
  }
  if (flight_) return JoinAnswer::refuse(JoinOutcome::NotAllowed, "a shot is in motion");
  const rules::Verdict verdict = rules::forfeit(game_, seat);
  game_ = verdict.next;
  const int winner = verdict.winner;
  const int won = ++seats_[static_cast<std::size_t>(winner)].racks_won;
  const std::string said = "seat " + std::to_string(seat) + protocol::kConcededTheRack;
  if (won < settings_.race_to) {
    // The race goes on: the next rack, broken as the settings say.
    startRack(nextBreaker(winner));
    last_verdict_ = said + "; rack " + std::to_string(rack_) + " to break";
  } else {
    last_verdict_ = said + ": seat " + std::to_string(winner) + " won the match";
  }
  touch();
  return seated(id_, seat, seats_[static_cast<std::size_t>(seat)].token);
}

JoinAnswer Match::addSpectator(const std::string& client) {
  spectators_.insert(client);  // not a change of the match: nothing to store, no new state
  return {JoinOutcome::Accepted, {}, id_, -1, 0};
}

bool Match::removeSpectator(const std::string& client) {
  return spectators_.erase(client) != 0;
}

void Match::pause(double seconds) {
  for (Seat& s : seats_) {
    if (s.away_since) *s.away_since += seconds;
  }
  if (flight_) {
    flight_->pacer.delay(seconds);
    flight_->view_done += seconds;
  }
  if (clock_start_) *clock_start_ += seconds;
  clock_not_before_ += seconds;
}

bool Match::clientGone(const std::string& client, double now) {
  bool seated = false;
  for (Seat& s : seats_) {
    if (!s.taken() || s.client != client) continue;
    seated = true;
    if (!s.away_since) {
      s.away_since = now;
      touch();
    }
  }
  removeSpectator(client);
  return seated;
}

bool Match::seats(const std::string& client) const {
  return std::any_of(seats_.begin(), seats_.end(),
                     [&](const Seat& s) { return s.taken() && s.client == client; });
}

bool Match::expireAway(double now, double grace) {
  for (int seat = 0; seat < 2; ++seat) {
    Seat& s = seats_[static_cast<std::size_t>(seat)];
    if (!s.away_since || now - *s.away_since < grace) continue;
    if (practice() && !flight_) {
      s = Seat{};  // nothing to forfeit at a practice table: the seat is free again
      touch();
      return true;
    }
    if (inPlay() && !pending_forfeit_) {
      const Seat& other = seats_[static_cast<std::size_t>(1 - seat)];
      if (!other.away_since) {
        forfeitSeat(seat, "did not come back");
        return true;
      }
      // Both players are gone: nobody wins a game nobody is there to play. Once both graces
      // have run out, the game is abandoned without a result (both seats free: it closes).
      if (now - *other.away_since < grace) continue;
      seats_ = {};
      touch();
      return true;
    }
    if (phase() == MatchPhase::Lobby || (phase() == MatchPhase::Over && !pending_forfeit_)) {
      // Nobody to forfeit to yet, or the game is decided: the seat is simply free again (a
      // finished match nobody came back to closes once it is empty).
      s = Seat{};
      touch();
      return true;
    }
  }
  return false;
}

// ---- Shots --------------------------------------------------------------------------------------

CommandAnswer Match::handleShot(const protocol::ShotRequest& command, double now) {
  CommandAnswer answer;
  answer.seat = command.seat;
  answer.seq = command.seq;
  answer.shot_number = shot_number_;
  CheckedCommand checked = checkCommand(*this, command);
  // A command its seat's key signed uses up its number, accepted or not: it cannot be replayed.
  if (checked.signature_valid) {
    seats_[static_cast<std::size_t>(command.seat)].last_seq = command.seq;
  }
  if (!checked.rejection.accepted()) {
    answer.rejection = std::move(checked.rejection);
    return answer;
  }
  ShotPlan& plan = checked.plan;
  if (!plan.shoots) return applyChoiceNow(command, *plan.choice, balls_);
  return runPlan(command, std::move(plan), now);
}

Result<rules::Verdict> Match::judge(const rules::GameState& state, const rules::Shot& shot) const {
  if (!practice()) return rules::judgeShot(rules(), state, shot, table().context);
  auto verdict = rules::judgePractice(shot, table().context);
  // At a practice table the cue ball is always in hand anywhere, for whoever shoots next.
  if (verdict) verdict->next.ball_in_hand = rules::BallInHand::Anywhere;
  return verdict;
}

int Match::cueBallFor(const rules::GameState& state) const {
  return practice() ? physics::kCueBall : rules::cueBallFor(rules(), state);
}

CommandAnswer Match::runPlan(const protocol::ShotRequest& command, ShotPlan plan, double now) {
  CommandAnswer answer;
  answer.seat = command.seat;
  answer.seq = command.seq;
  answer.shot_number = shot_number_;
  physics::CueShot cue = command.cue;
  cue.ball = cueBallFor(plan.state);  // three-cushion: the shooter's own ball
  auto outcome = runner_->run(plan.before, cue, options_.snapshot_hz, options_.max_shot_time);
  if (!outcome) {
    answer.rejection = {Reject::Malformed, "the physics refused the shot: " + outcome.error()};
    return answer;
  }
  rules::Shot shot{plan.before, plan.intent, outcome->events, outcome->balls, false};
  auto verdict = judge(plan.state, shot);
  if (!verdict) {
    answer.rejection = {Reject::Malformed, "the rules refused the shot: " + verdict.error()};
    return answer;
  }
  if (practice()) rememberStep(command, plan);
  answer.record = ShotRecord{command,     shot_number_ + 1, true,           plan.state, plan.before,
                             plan.intent, outcome->events,  outcome->balls, *verdict};
  // Accepted: the shot is in motion from now on.
  ShotReport report{command.seat,        command.seq, shot_number_ + 1, std::move(outcome->events),
                    std::move(*verdict), {}};
  auto after = tableAfter(report.verdict, outcome->balls);
  auto frames = framesOf(*outcome);
  FramePacer pacer(timesOf(frames), now, options_.unpaced);
  // Paced or not, the shooter's view plays the shot in real time.
  const double view_done = now + frames.back().t + kViewDelay;
  flight_.emplace(
      Flight{std::move(report), std::move(frames), std::move(after), std::move(pacer), view_done});
  clock_start_.reset();
  clock_pending_ = false;
  answer.shot_number = shot_number_ + 1;
  answer.in_motion = true;
  return answer;
}

CommandAnswer Match::applyChoiceNow(const protocol::ShotRequest& command,
                                    const rules::Verdict& verdict,
                                    std::vector<physics::Ball> balls) {
  CommandAnswer answer;
  // Field by field: the aggregate with `{}` members made g++ 12 at -O3 warn that the empty
  // intent's string "may be used uninitialized" (-Wmaybe-uninitialized, a false positive).
  ShotRecord& record = answer.record.emplace();
  record.command = command;
  record.shot_number = shot_number_;
  record.shoots = false;
  record.state = game_;
  record.before = balls;
  record.after = balls;
  record.verdict = verdict;
  auto after = tableAfter(verdict, std::move(balls));
  commit(verdict, std::move(after), command.seat);
  answer.seat = command.seat;
  answer.seq = command.seq;
  answer.shot_number = shot_number_;
  answer.done = ShotReport{command.seat, command.seq, shot_number_, {}, verdict, {}};
  return answer;
}

DueFrames Match::takeDueFrames(double now) {
  if (!flight_) return {};
  const FrameRange range = flight_->pacer.take(now);
  const std::span<const physics::Sample> all(flight_->frames);
  return {static_cast<std::uint32_t>(range.first), flight_->report.shot_number,
          all.subspan(range.first, range.size())};
}

std::optional<double> Match::nextFrameDue() const {
  if (!flight_) return std::nullopt;
  return flight_->pacer.nextDue();
}

std::optional<ShotReport> Match::finishShot() {
  if (!flight_ || !flight_->pacer.done()) return std::nullopt;
  Flight flight = std::move(*flight_);
  flight_.reset();
  ShotReport report = flight.report;
  land(std::move(flight));
  return report;
}

void Match::land(Flight flight) {
  ++shot_number_;
  commit(flight.report.verdict, std::move(flight.after), flight.report.seat);
  if (clock_pending_) clock_not_before_ = flight.view_done;
  if (pending_forfeit_) {
    const int loser = *pending_forfeit_;
    pending_forfeit_.reset();
    if (inPlay()) forfeitSeat(loser, "left");
  }
}

std::uint32_t Match::shotInMotion() const {
  return flight_ ? flight_->report.shot_number : 0;
}

// ---- State --------------------------------------------------------------------------------------

MatchPhase Match::phase() const {
  if (closed_) return MatchPhase::Closed;
  if (!started_) return MatchPhase::Lobby;
  switch (game_.phase) {
    case rules::Phase::Break:
      return MatchPhase::Break;
    case rules::Phase::Open:
      return MatchPhase::Open;
    case rules::Phase::Assigned:
      return MatchPhase::Assigned;
    case rules::Phase::Over:
      return MatchPhase::Over;
  }
  return MatchPhase::Lobby;
}

bool Match::inPlay() const {
  const MatchPhase p = phase();
  return p == MatchPhase::Break || p == MatchPhase::Open || p == MatchPhase::Assigned;
}

bool Match::setPosition(const rules::GameState& state, std::vector<physics::Ball> balls) {
  if (!started_ || flight_) return false;
  game_ = state;
  balls_ = std::move(balls);
  touch();
  return true;
}

void Match::close(std::string why) {
  closed_ = true;
  if (!why.empty()) last_verdict_ = std::move(why);
  flight_.reset();
  touch();
}

MatchSnapshot Match::snapshot() const {
  Match settled = *this;
  if (settled.flight_) {
    // Lands the shot in motion at once on the copy: its frames are not needed.
    Flight flight = std::move(*settled.flight_);
    settled.flight_.reset();
    flight.frames.clear();
    settled.land(std::move(flight));
  }
  MatchSnapshot out;
  out.id = id_;
  out.name = name_;
  out.rack_seed = rack_seed_;
  out.rack_generator = rack_generator_;
  out.layouts = settled.layouts_;
  out.started = settled.started_;
  out.closed = settled.closed_;
  out.shot_number = settled.shot_number_;
  out.rack = settled.rack_;
  out.revision = settled.revision_;
  out.last_verdict = settled.last_verdict_;
  out.game = settled.game_;
  out.balls = settled.balls_;
  out.seats = settled.seats_;
  out.settings = settings_;
  return out;
}

bool Match::empty() const {
  return !seats_[0].taken() && !seats_[1].taken() && spectators_.empty();
}

void Match::startRack(int breaker) {
  game_ = rules::newRackOf(settings_.game, breaker);
  balls_ = layout(layouts_++, settings_.game);
  ++rack_;
  started_ = true;
  last_verdict_.clear();
  for (Seat& s : seats_) {
    s.fouls = 0;
    s.wants_rematch = false;
  }
  extensions_ = settings_.clockOn() ? std::array<int, 2>{1, 1} : std::array<int, 2>{0, 0};
  restartClock(0.0);
  touch();
}

Result<std::shared_ptr<ShotRunner>> Match::runnerFor(rules::Game game) const {
  if (!options_.tables) return Result<std::shared_ptr<ShotRunner>>::ok(runner_);
  return options_.tables->forGame(game);
}

std::vector<physics::Ball> Match::layout(std::uint64_t number, rules::Game game) const {
  return game::rackLayout(table(), rack_seed_ + number, rules::rackTypeOf(game), rack_generator_);
}

void Match::commit(const rules::Verdict& verdict, std::vector<physics::Ball> after, int shooter) {
  game_ = verdict.next;
  balls_ = std::move(after);
  last_verdict_ = rules::describe(verdict);
  if (!verdict.legal()) ++seats_[static_cast<std::size_t>(shooter)].fouls;
  if (verdict.rerack) {
    // A re-rack is a fresh rack of the same game: new layout, fouls cleared.
    balls_ = layout(layouts_++, settings_.game);
    for (Seat& s : seats_) s.fouls = 0;
  }
  restartClock(0.0);
  if (verdict.game_over && verdict.winner >= 0) {
    const int won = ++seats_[static_cast<std::size_t>(verdict.winner)].racks_won;
    // A race goes on with the next rack until a player has won race_to of them.
    if (won < settings_.race_to) {
      const std::string last = last_verdict_;
      startRack(nextBreaker(verdict.winner));
      last_verdict_ = last + "; rack " + std::to_string(rack_) + " to break";
    }
  }
  touch();
}

void Match::forfeitSeat(int loser, const std::string& why) {
  if (flight_) {
    pending_forfeit_ = loser;  // judged once the shot in motion is done
    return;
  }
  const rules::Verdict verdict = rules::forfeit(game_, loser);
  game_ = verdict.next;
  last_verdict_ = "seat " + std::to_string(loser) + " " + why + ": " + rules::describe(verdict);
  ++seats_[static_cast<std::size_t>(verdict.winner)].racks_won;
  touch();
}

std::vector<physics::Ball> Match::tableAfter(const rules::Verdict& verdict,
                                             std::vector<physics::Ball> balls) {
  for (const auto& respot : verdict.respots) {
    for (auto& b : balls) {
      if (b.id != respot.id) continue;
      b = physics::Ball{};
      b.id = respot.id;
      b.pos = physics::Vec3(respot.pos.x(), respot.pos.y(), table().context.ball_radius);
    }
  }
  return balls;
}

// ---- Shot clock -------------------------------------------------------------------------------

void Match::restartClock(double not_before) {
  clock_start_.reset();
  clock_pending_ = settings_.clockOn();
  clock_not_before_ = not_before;
  clock_total_ = settings_.shot_clock;
  clock_warned_ = false;
}

std::optional<double> Match::clockLeft(double now) const {
  if (!clock_start_ || flight_ || !inPlay()) return std::nullopt;
  return std::max(0.0, clock_total_ - std::max(0.0, now - *clock_start_));
}

std::optional<CommandAnswer> Match::tickClock(double now) {
  if (!settings_.clockOn() || flight_ || !inPlay()) return std::nullopt;
  if (clock_pending_) {
    clock_pending_ = false;
    clock_start_ = std::max(now, clock_not_before_);
    touch();
    return std::nullopt;
  }
  const auto left = clockLeft(now);
  if (!left) return std::nullopt;
  if (*left > 0.0) {
    if (!clock_warned_ && *left <= settings_.warningAt()) {
      clock_warned_ = true;
      touch();  // the state shows the warning
    }
    return std::nullopt;
  }
  int& extensions = extensions_[static_cast<std::size_t>(game_.shooter)];
  if (extensions > 0) {
    --extensions;
    clock_total_ += settings_.shot_clock;
    clock_warned_ = false;
    touch();
    return std::nullopt;
  }
  return timeOut();
}

std::optional<CommandAnswer> Match::runOutClock() {
  if (flight_ || !inPlay()) return std::nullopt;
  return timeOut();
}

// The clock ran out: judged as a safety without a strike (a pending choice taken as playing on).
CommandAnswer Match::timeOut() {
  rules::GameState state = game_;
  std::vector<physics::Ball> balls = balls_;
  if (!state.options.empty()) {
    const auto& offered = state.options;
    const bool play_on =
        std::find(offered.begin(), offered.end(), rules::Choice::PlayOn) != offered.end();
    auto chosen = rules::applyChoiceFor(
        rules(), state, play_on ? rules::Choice::PlayOn : offered[0], balls, table().context);
    if (chosen && !chosen->rerack) {
      state = chosen->next;
      balls = tableAfter(*chosen, std::move(balls));
    }
  }
  const int seat = state.shooter;
  rules::Shot shot{balls, rules::Intent::safe(), {}, balls, true};
  auto verdict = rules::judgeShot(rules(), state, shot, table().context);
  CommandAnswer answer;
  answer.seat = seat;
  answer.shot_number = shot_number_;
  if (!verdict) {
    // Not expected: the rules judge every time-out. The clock stops rather than loop.
    clock_start_.reset();
    answer.rejection = {Reject::Malformed, "the rules refused the time-out: " + verdict.error()};
    return answer;
  }
  ShotRecord& record = answer.record.emplace();
  record.command.match = id_;
  record.command.seat = seat;
  record.shot_number = shot_number_;
  record.shoots = false;
  record.state = state;
  record.before = balls;
  record.intent = shot.intent;
  record.after = balls;
  record.verdict = *verdict;
  commit(*verdict, tableAfter(*verdict, std::move(balls)), seat);
  last_verdict_ = "shot clock: " + last_verdict_;
  answer.done = ShotReport{seat, 0, shot_number_, {}, *verdict, {}};
  return answer;
}

int Match::nextBreaker(int rack_winner) const {
  if (settings_.breaks == protocol::BreakOrder::Winner && rack_winner >= 0) return rack_winner;
  return rules::opponentOf(game_.breaker);
}

std::optional<int> Match::seatOf(const protocol::SeatRequest& r) const {
  // The seat named, else the one bound to the request's key (the token is public: it only names
  // a holding, so it never picks a seat by itself).
  for (int s = 0; s < 2; ++s) {
    const Seat& seat = seats_[static_cast<std::size_t>(s)];
    if (!seat.taken() || (r.seat != -1 && r.seat != s)) continue;
    if (seat.public_key == r.public_key) return s;
  }
  return std::nullopt;
}

}  // namespace pool::server
