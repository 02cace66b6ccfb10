// Joining, following and shooting in one match from this screen.
#include "client/app/match_session.h"

#include "core/hex.h"

#include <algorithm>
#include <variant>

#include "client/app/shot_story.h"
#include "protocol/seat_request.h"

namespace pool::app {
namespace {

// How long a state counting a new shot waits for that shot's frames before the table is shown
// at rest (a spectator who came late never gets them), s.
constexpr double kFrameGrace = 1.0;
// How long a join request waits for its answer before it is sent again, s.
constexpr double kJoinRetry = 2.0;

}  // namespace

MatchSession::MatchSession(SessionOptions options) : options_(std::move(options)) {
  const int count = options_.hotseat ? 2 : 1;
  for (int i = 0; i < count; ++i) {
    const std::string name =
        options_.hotseat ? options_.name + " " + std::to_string(i + 1) : options_.name;
    std::optional<protocol::KeyPair> key;
    std::optional<client::PlayerIdentity> identity;
    if (!options_.identity_dir.empty()) {
      identity.emplace(options_.identity_dir, name);
      auto kept = identity->key();
      if (kept) {
        key = *kept;
      } else {
        note("player key: " + kept.error() + " (playing with a new key)", true);
        identity.reset();
      }
    }
    // Server keys are pinned beside the players' identities (in memory without them).
    client::ClientOptions client_options{options_.domain, "", name, {}, {}};
    if (!options_.identity_dir.empty()) {
      client_options.server_pins = options_.identity_dir.parent_path() / "servers";
    }
    client_options.log = [this](const std::string& line, bool problem) { note(line, problem); };
    clients_.push_back(std::make_unique<client::GameClient>(std::move(client_options), key));
    clients_.back()->setTableSettings(options_.table_settings);
    saved_.push_back(identity ? identity->seat() : std::nullopt);
    if (saved_.back()) clients_.back()->noteSequence(saved_.back()->last_seq);
    identities_.push_back(std::move(identity));
  }
  awaiting_.assign(clients_.size(), false);
  away_revision_.assign(clients_.size(), 0);
}

MatchSession::~MatchSession() = default;

const client::Lobby& MatchSession::lobby() const {
  return clients_.front()->lobby();
}

const client::PlayerBook& MatchSession::players() const {
  return clients_.front()->players();
}

const std::map<std::string, protocol::TournamentView>& MatchSession::tournaments() const {
  return clients_.front()->tournaments();
}

void MatchSession::note(std::string text, bool problem) {
  notes_.push_back({std::move(text), problem});
}

std::vector<SessionNote> MatchSession::takeNotes() {
  auto out = std::move(notes_);
  notes_.clear();
  return out;
}

void MatchSession::play(const std::string& match) {
  stored_.close();
  want_ = Want::Play;
  wanted_match_ = match;
  stage_ = SessionStage::Joining;
  startPending();
}

void MatchSession::spectate(const std::string& match) {
  stored_.close();
  want_ = Want::Spectate;
  wanted_match_ = match == "any" ? std::string() : match;
  stage_ = SessionStage::Joining;
  startPending();
}

void MatchSession::leave() {
  if (!match_.empty()) {
    for (auto& c : clients_) c->requestLeave(match_);
  }
  match_.clear();
  want_ = Want::None;
  awaiting_.assign(clients_.size(), false);
  stage_ = SessionStage::Lobby;
  playback_.clear();
  unanswered_.reset();
  shots_seen_ = 0;
  frames_due_until_ = 0.0;
  banner_.clear();
  shot_log_.clear();
  verdict_heard_.clear();
  replay_.clear();
  names_ = seatNames(nullptr);
}

void MatchSession::enterTournament(const std::string& tournament) {
  clients_.front()->requestEnter(tournament);
}

void MatchSession::openTournament(const protocol::MatchSettings& settings,
                                  const protocol::TournamentOpening& opening) {
  clients_.front()->requestOpenTournament(settings, opening);
}

std::string MatchSession::playerKey() const {
  return hexOf(clients_.front()->key().publicKey());
}

void MatchSession::rematch() {
  for (auto& c : clients_) {
    if (c->seat()) c->requestRematch();
  }
}

bool MatchSession::concede() {
  const client::MatchView* v = view();
  if (!v || !client::inPlay(v->phase)) return false;
  for (auto& c : clients_) {
    const auto& seat = c->seat();
    if (!seat || seat->match != match_) continue;
    if (clients_.size() > 1 && seat->seat != v->shooter) continue;
    c->requestConcede();
    return true;
  }
  return false;
}

bool MatchSession::joining() const {
  return std::find(awaiting_.begin(), awaiting_.end(), true) != awaiting_.end();
}

void MatchSession::sendJoin(std::size_t i) {
  if (want_ == Want::Play && saved_[i] && client::takesBackKeptSeat(*saved_[i], wanted_match_)) {
    // A seat this player held when the window last ran: take it back first.
    clients_[i]->requestRejoin(saved_[i]->match, saved_[i]->token, saved_[i]->seat);
  } else if (want_ == Want::Play) {
    clients_[i]->requestSeat(wanted_match_);
  } else {
    clients_[i]->requestSpectate(wanted_match_);
  }
  awaiting_[i] = true;
  join_sent_at_ = last_poll_;
}

void MatchSession::startPending() {
  // Requests go out once the lobby names a match to send them to.
  if (want_ == Want::None || joining() || !match_.empty()) return;
  const bool rejoin = want_ == Want::Play && saved_.front().has_value() &&
                      client::takesBackKeptSeat(*saved_.front(), wanted_match_);
  if (wanted_match_.empty() && !rejoin) {
    const auto found = want_ == Want::Play ? lobby().lowestWithFreeSeat() : lobby().firstInPlay();
    if (!found) return;
    wanted_match_ = *found;
  }
  // A practice table is opened by one player (with two on this screen, the first): two "new"
  // requests would open two tables.
  const bool practice = options_.table_settings && options_.table_settings->practice;
  const std::size_t count = want_ == Want::Play && !practice ? clients_.size() : 1;
  for (std::size_t i = 0; i < count; ++i) sendJoin(i);
}

void MatchSession::retryJoins() {
  // A request written before the server's reader matched ours is lost: ask again.
  if (want_ == Want::None || last_poll_ - join_sent_at_ < kJoinRetry) return;
  for (std::size_t i = 0; i < clients_.size(); ++i) {
    if (awaiting_[i]) sendJoin(i);
  }
}

void MatchSession::keepSeat(std::size_t from) {
  const auto& seat = clients_[from]->seat();
  if (!identities_[from] || !seat) return;
  const client::SeatRecord record{seat->match, seat->seat, seat->token,
                                  clients_[from]->lastSequence()};
  if (auto error = identities_[from]->keepSeat(record); !error.empty()) {
    note("cannot keep the seat for a restart: " + error, true);
  }
}

bool MatchSession::onRejoinAnswer(const client::JoinAnswer& answer, std::size_t from) {
  if (answer.accepted()) {
    note("took back seat " + std::to_string(answer.seat + 1) + " in " + answer.match);
    keepSeat(from);
    saved_[from].reset();
    return false;  // the common path below follows the match
  }
  if (!saved_[from]) return true;  // a rejoin after being shown away, refused: nothing to undo
  note("seat in " + saved_[from]->match + " is gone (" + client::toString(answer.outcome) +
           "): finding a table",
       true);
  saved_[from].reset();
  if (identities_[from]) identities_[from]->forgetSeat();
  awaiting_[from] = false;
  startPending();  // a free table, as if no seat had been kept
  return true;
}

void MatchSession::rejoinIfAway(const client::MatchView& view) {
  for (std::size_t i = 0; i < clients_.size(); ++i) {
    const auto& seat = clients_[i]->seat();
    if (!seat || seat->match != view.match) continue;
    const auto& shown = view.seats[static_cast<std::size_t>(seat->seat)];
    if (shown.connected || away_revision_[i] == view.revision) continue;
    // The server takes us for gone (it restarted, or our lease ran out while we were starved).
    away_revision_[i] = view.revision;
    note("the server shows seat " + std::to_string(seat->seat + 1) + " away: taking it back");
    clients_[i]->requestRejoin(seat->match, seat->token, seat->seat);
  }
}

void MatchSession::onAnswer(const client::JoinAnswer& answer, std::size_t from) {
  // An entry (or a tournament opened) changes no seat: it is only told.
  if (answer.action == client::JoinAction::Enter) {
    if (answer.accepted()) {
      note("entered tournament " + answer.match);
    } else {
      note("tournament: " + answer.reason, true);
    }
    return;
  }
  if (answer.action == client::JoinAction::Leave && answer.accepted() && identities_[from]) {
    identities_[from]->forgetSeat();
  }
  if (answer.action == client::JoinAction::Concede && !answer.accepted()) {
    note("concede refused: " + answer.reason, true);
    return;
  }
  if (answer.action == client::JoinAction::Leave || answer.action == client::JoinAction::Rematch ||
      answer.action == client::JoinAction::Concede) {
    return;
  }
  if (answer.action == client::JoinAction::Rejoin && onRejoinAnswer(answer, from)) return;
  if (answer.action == client::JoinAction::Seat && answer.accepted()) keepSeat(from);
  // A repeated request's second answer changes nothing.
  if (!awaiting_[from]) return;
  awaiting_[from] = false;
  if (!answer.accepted()) {
    note("join " + answer.match + ": " + client::toString(answer.outcome) +
             (answer.reason.empty() ? "" : " (" + answer.reason + ")"),
         true);
    if (!joining() && match_.empty()) {
      stage_ = SessionStage::Lobby;
      want_ = Want::None;
    }
    return;
  }
  if (want_ == Want::None) {
    // Cancelled while the request was on its way: give the place back.
    for (auto& c : clients_) c->requestLeave(answer.match);
    return;
  }
  match_ = answer.match;
  stage_ = want_ == Want::Play ? SessionStage::Playing : SessionStage::Spectating;
  note(answer.action == client::JoinAction::Spectate
           ? "watching " + answer.match
           : "seat " + std::to_string(answer.seat + 1) + " in " + answer.match);
}

void MatchSession::onReport(const client::ShotReport& report) {
  if (report.match != match_) return;
  const auto seats = localSeats();
  const bool ours = std::find(seats.begin(), seats.end(), report.seat) != seats.end();
  if (!report.accepted) {
    if (ours && unanswered_ == report.seq) {
      unanswered_.reset();
      note("refused: " + std::string(client::toString(report.reject_reason)) + " " +
               report.reject_text,
           true);
    }
    return;
  }
  if (report.final()) {
    last_verdict_ = report.verdict_text;
    // A practice table's change (no stroke) says what it did in its own words.
    const bool change = report.events.empty() && practiceTable();
    const rules::Game game = view() ? view()->settings.game : rules::Game::EightBall;
    banner_ = change ? report.verdict_text : shotStory(report, names_, game);
    shot_log_.push_back(banner_);
    while (shot_log_.size() > kLogKept) shot_log_.pop_front();
    if (listener_) listener_->onShot(report);
  } else if (ours) {
    note("shot " + std::to_string(report.seq) + " of seat " + std::to_string(report.seat + 1) +
         " accepted");
  }
}

void MatchSession::handle(client::ClientEvent& event, std::size_t from, double now) {
  if (auto* answer = std::get_if<client::JoinAnswer>(&event)) return onAnswer(*answer, from);
  // Everything else reaches every client alike: the first one's copy is used.
  if (from != 0) return;
  if (auto* frame = std::get_if<client::TableFrame>(&event)) {
    if (frame->match != match_) return;
    if (frame->shot_number >= shots_seen_) frames_due_until_ = 0.0;
    if (listener_) listener_->onFrame(*frame);
    replay_.record(*frame);
    playback_.push(std::move(*frame), now);
  } else if (auto* view = std::get_if<client::MatchView>(&event)) {
    if (view->match != match_) return;
    if (stage_ == SessionStage::Playing) rejoinIfAway(*view);
    // A state that counts a new shot may overtake the shot's frames: wait a little for them.
    const auto playing = playback_.shot();
    if (view->shot_number > shots_seen_ && (!playing || *playing < view->shot_number)) {
      frames_due_until_ = now + kFrameGrace;
    }
    shots_seen_ = std::max(shots_seen_, view->shot_number);
    // Our shot is answered by the state that counts it (other states may come in between).
    if (unanswered_ && view->shot_number >= awaited_shots_) unanswered_.reset();
    if (!view->last_verdict.empty()) last_verdict_ = view->last_verdict;
    for (std::size_t s = 0; s < 2; ++s) {
      if (!view->seats[s].name.empty()) names_[s] = view->seats[s].name;
    }
    if (banner_.empty() && !view->last_verdict.empty()) {
      banner_ = verdictInWords(view->last_verdict, names_);
    }
    // A concession is no shot: its words come with the state, once.
    if (view->last_verdict != verdict_heard_) {
      verdict_heard_ = view->last_verdict;
      if (verdict_heard_.find(protocol::kConcededTheRack) != std::string::npos) {
        banner_ = verdictInWords(verdict_heard_, names_);
        shot_log_.push_back(banner_);
        while (shot_log_.size() > kLogKept) shot_log_.pop_front();
        note(banner_);
      }
    }
  } else if (auto* report = std::get_if<client::ShotReport>(&event)) {
    onReport(*report);
  } else if (auto* stored = std::get_if<protocol::HistoryShot>(&event)) {
    stored_.take(std::move(*stored), now);
  } else if (auto* aim = std::get_if<protocol::AimSample>(&event)) {
    // Our own seats' aims come back relayed: this screen draws its own cue.
    const auto local = localSeats();
    if (aim->match != match_ || std::find(local.begin(), local.end(), aim->seat) != local.end()) {
      return;
    }
    follower_.receive(*aim, now);
  }
}

void MatchSession::poll(double now) {
  last_poll_ = now;
  for (std::size_t i = 0; i < clients_.size(); ++i) {
    for (auto& event : clients_[i]->poll()) handle(event, i, now);
  }
  startPending();
  retryJoins();
  askStored(now);
  recent_.see(lobby());
  // The followed cue goes when its turn does: a new shot counted, or the shot's motion drawn.
  const client::MatchView* v = view();
  if (const auto& latest = follower_.latest();
      latest && (!v || v->match != latest->match || v->shot_number != latest->shot_number ||
                 v->shooter != latest->seat)) {
    follower_.forget();
  }
  follower_.advance(now);
}

bool MatchSession::showStored(const std::string& match, std::uint32_t shot) {
  if (stage_ != SessionStage::Lobby || match.empty()) return false;
  const client::LobbyEntry* entry = lobby().find(match);
  stored_.open(match, shot, entry ? entry->shot_number : 0);
  return true;
}

void MatchSession::askStored(double now) {
  const auto shot = stored_.due(now);
  if (!shot) return;
  client::GameClient& asker = *clients_.front();
  if (!history_open_) {
    asker.openHistory();
    history_open_ = true;
  }
  auto request = asker.requestHistory(stored_.match(), *shot, 1);
  if (request) {
    stored_.asked(*request, now);
  } else {
    stored_.notAsked(request.error(), now);
  }
}

void MatchSession::sendAim(int seat, const AimState& aim, const Eigen::Vector2d& cue_ball,
                           bool stroke, double now) {
  const client::MatchView* v = view();
  if (!v) return;
  protocol::AimSample sample;
  sample.shot_number = v->shot_number;
  sample.yaw = aim.yaw;
  sample.tip_side = aim.tip_side;
  sample.tip_height = aim.tip_height;
  sample.elevation = aim.elevation;
  sample.power = aim.power;
  sample.stroke = stroke;
  sample.cue_ball_x = cue_ball.x();
  sample.cue_ball_y = cue_ball.y();
  if (!pacer_.due(sample, now)) return;
  for (auto& c : clients_) {
    if (!c->seat() || c->seat()->match != match_ || c->seat()->seat != seat) continue;
    if (!c->sendAim(sample)) ++aims_not_sent_;
    return;
  }
}

std::optional<FollowedAim> MatchSession::followedAim() const {
  return follower_.shown();
}

std::optional<protocol::AimSample> MatchSession::latestAim() const {
  if (!follower_.shown()) return std::nullopt;
  return follower_.latest();
}

std::uint64_t MatchSession::aimDropped() const {
  std::uint64_t n = 0;
  for (const auto& c : clients_) n += c->aimDropped();
  return n;
}

void MatchSession::wait(std::chrono::nanoseconds timeout) const {
  clients_.front()->wait(timeout);
}

const client::MatchView* MatchSession::view() const {
  return match_.empty() ? nullptr : clients_.front()->state(match_);
}

bool MatchSession::inMotion() const {
  const client::MatchView* v = view();
  return playback_.inMotion(v ? v->shot_number : 0) || last_poll_ < frames_due_until_;
}

std::optional<std::vector<physics::Ball>> MatchSession::balls(double now) {
  if (playback_.shot()) {
    auto moving = playback_.sample(now);
    if (inMotion()) return moving;
  }
  if (const auto* v = view()) return v->balls;
  return std::nullopt;
}

std::vector<int> MatchSession::localSeats() const {
  std::vector<int> seats;
  for (const auto& c : clients_) {
    if (c->seat() && c->seat()->match == match_) seats.push_back(c->seat()->seat);
  }
  return seats;
}

void MatchSession::setTableSettings(std::optional<protocol::MatchSettings> settings) {
  options_.table_settings = settings;
  for (auto& c : clients_) c->setTableSettings(settings);
}

bool MatchSession::practiceTable() const {
  const auto* v = view();
  return v && v->settings.practice;
}

Result<std::uint32_t> MatchSession::practice(protocol::PracticeRequest request) {
  const auto* v = view();
  if (!v || !v->settings.practice) return Result<std::uint32_t>::fail("not a practice table");
  if (inMotion() || unanswered_) return Result<std::uint32_t>::fail("wait: the table is busy");
  for (auto& c : clients_) {
    if (!c->seat() || c->seat()->match != match_) continue;
    const bool shoots = request.action == protocol::PracticeAction::Again;
    auto sent = c->practice(std::move(request));
    if (sent) {
      unanswered_ = *sent;
      // Again is a stroke, counted by the next shot number; the others by any new state.
      awaited_shots_ = shoots ? v->shot_number + 1 : 0;
    }
    return sent;
  }
  return Result<std::uint32_t>::fail("no seat held here");
}

int MatchSession::localShooter() const {
  const auto* v = view();
  if (!v || !client::inPlay(v->phase) || v->shooter < 0 || inMotion() || unanswered_) return -1;
  const auto seats = localSeats();
  // At a practice table every local seat may shoot at any time: the first one aims.
  if (v->settings.practice) return seats.empty() ? -1 : seats.front();
  return std::find(seats.begin(), seats.end(), v->shooter) != seats.end() ? v->shooter : -1;
}

Result<std::uint32_t> MatchSession::shoot(int seat, protocol::ShotRequest request) {
  for (auto& c : clients_) {
    if (!c->seat() || c->seat()->match != match_ || c->seat()->seat != seat) continue;
    const client::MatchView* v = view();
    const bool shoots = protocol::optionShoots(request.option);
    const protocol::ShotRequest copy = request;
    auto sent = c->shoot(std::move(request));
    if (sent) {
      if (shoots) last_shot_ = copy;
      unanswered_ = *sent;
      // A stroke is counted by the next state's shot number; a re-rack by any new state.
      awaited_shots_ = v && shoots ? v->shot_number + 1 : 0;
    }
    return sent;
  }
  return Result<std::uint32_t>::fail("seat " + std::to_string(seat) + " is not held here");
}

}  // namespace pool::app
