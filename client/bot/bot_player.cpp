// The bot's state machine over the client session.
#include "client/bot/bot_player.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>

#include "client/bot/bot_aim.h"
#include "client/bot/shot_command.h"

namespace pool::bot {
namespace {

constexpr const char* kDefaultTable = "wpa-9ft";
constexpr double kMaxRetryDelay = 1.0;  // s between retries after rejections

}  // namespace

const char* toString(BotStage stage) {
  switch (stage) {
    case BotStage::FindingMatch:
      return "finding_match";
    case BotStage::Joining:
      return "joining";
    case BotStage::Playing:
      return "playing";
    case BotStage::SeatLost:
      return "seat_lost";
    case BotStage::Finished:
      return "finished";
    case BotStage::Failed:
      return "failed";
  }
  return "unknown";
}

BotPlayer::BotPlayer(client::GameClient& client, BotConfig config,
                     std::optional<client::SeatRecord> saved)
    : client_(client),
      config_(std::move(config)),
      saved_(std::move(saved)),
      noise_(config_.skill.value_or(1.0), config_.seed),
      level_rng_(config_.seed) {
  if (saved_) {
    target_ = saved_->match;
    client_.noteSequence(saved_->last_seq);
  } else {
    target_ = config_.match;
  }
}

void BotPlayer::step(double now) {
  if (done()) return;
  for (const auto& event : client_.poll()) {
    handle(event, now);
    if (done()) return;
  }
  act(now);
}

void BotPlayer::handle(const client::ClientEvent& event, double now) {
  std::visit(
      [&](const auto& e) {
        using E = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<E, client::JoinAnswer>) onAnswer(e, now);
        if constexpr (std::is_same_v<E, client::LobbyEntry>) onLobby(e, now);
        if constexpr (std::is_same_v<E, client::MatchGone>) onGone(e, now);
        if constexpr (std::is_same_v<E, client::MatchView>) onState(e, now);
        if constexpr (std::is_same_v<E, client::ShotReport>) onReport(e, now);
      },
      event);
}

// ---- Joining ------------------------------------------------------------------------------------

void BotPlayer::onAnswer(const client::JoinAnswer& answer, double now) {
  if (concede_request_ && answer.request == *concede_request_) {
    concede_request_.reset();
    if (!answer.accepted()) {
      spdlog::warn("concession refused: {} {}", client::toString(answer.outcome), answer.reason);
      conceded_rack_ = 0;  // tried again a little later
      retry_at_ = now + config_.join_retry;
    }
    return;
  }
  if (!join_request_ || answer.request != *join_request_) return;
  join_request_.reset();
  if (answer.accepted()) {
    spdlog::info("{} {} seat {}", client::toString(answer.action), answer.match, answer.seat);
    target_ = answer.match;
    stage_ = BotStage::Playing;
    // Turn bookkeeping starts over: a restarted server numbers shots and revisions from scratch.
    pending_seq_.reset();
    blocked_revision_.reset();
    turn_revision_.reset();
    wait_for_shot_ = 0;
    rejections_ = 0;
    saveSeat();
    return;
  }
  spdlog::warn("{} {} refused: {} {}", client::toString(answer.action), answer.match,
               client::toString(answer.outcome), answer.reason);
  switch (answer.outcome) {
    case client::JoinOutcome::VersionMismatch:
    case client::JoinOutcome::BadName:
      stage_ = BotStage::Failed;
      failure_ = std::string(client::toString(answer.outcome)) + ": " + answer.reason;
      return;
    case client::JoinOutcome::BadToken:
    case client::JoinOutcome::NoSuchMatch:
      // The seat we remembered is gone (a restarted server, a closed match): sit anew.
      if (answer.action == client::JoinAction::Rejoin) {
        saved_.reset();
        target_ = config_.match;
      }
      break;
    default:
      break;
  }
  stage_ = BotStage::FindingMatch;
  join_sent_at_ = now;  // the next attempt waits a retry period
}

void BotPlayer::onLobby(const client::LobbyEntry& entry, double now) {
  const auto& seat = client_.seat();
  if (stage_ == BotStage::Playing && seat && entry.match == seat->match &&
      entry.players[static_cast<std::size_t>(seat->seat)] != client_.name()) {
    // Our seat shows someone else or nobody: the server restarted or gave the seat away.
    loseSeat(now, "the lobby no longer shows us in our seat");
  }
}

void BotPlayer::onGone(const client::MatchGone& gone, double now) {
  if (stage_ == BotStage::Playing && gone.match == target_) {
    loseSeat(now, gone.disposed ? "the match was closed" : "the server vanished");
  }
}

void BotPlayer::loseSeat(double now, const std::string& why) {
  spdlog::warn("lost seat in {}: {}", target_, why);
  const auto& seat = client_.seat();
  if (seat)
    saved_ = client::SeatRecord{seat->match, seat->seat, seat->token, client_.lastSequence()};
  stage_ = BotStage::SeatLost;
  lost_at_ = now;
  pending_seq_.reset();
}

void BotPlayer::act(double now) {
  switch (stage_) {
    case BotStage::FindingMatch:
      findMatch(now);
      break;
    case BotStage::Joining:
      if (now - join_sent_at_ >= config_.join_retry) sendJoin(now);
      break;
    case BotStage::SeatLost:
      // The wait for the lost match starts once a server is seen again: a server that was stopped
      // comes back with its lobby entries one by one, in no set order.
      if (client_.lobby().empty()) lost_at_ = now;
      if (saved_ && client_.lobby().find(saved_->match)) {
        sendJoin(now);
      } else if (!client_.lobby().empty() && now - lost_at_ >= config_.lost_seat_wait) {
        saved_.reset();
        target_ = config_.match;
        stage_ = BotStage::FindingMatch;
      }
      break;
    case BotStage::Playing:
      maybeShoot(now);
      break;
    default:
      break;
  }
}

void BotPlayer::findMatch(double now) {
  if (now - join_sent_at_ < config_.join_retry) return;
  if (!saved_ && config_.match.empty()) {
    if (client_.lobby().empty()) {
      lobby_seen_at_.reset();
      return;  // no server yet
    }
    if (!lobby_seen_at_) lobby_seen_at_ = now;
    if (now - *lobby_seen_at_ < kLobbySettle) return;
    const auto free = client_.lobby().lowestWithFreeSeat();
    if (!free) return;  // no server yet, or every match is full: keep waiting
    target_ = *free;
  }
  sendJoin(now);
}

void BotPlayer::sendJoin(double now) {
  join_request_ = saved_ ? client_.requestRejoin(saved_->match, saved_->token, saved_->seat)
                         : client_.requestSeat(target_, -1);
  join_sent_at_ = now;
  stage_ = BotStage::Joining;
}

void BotPlayer::saveSeat() {
  const auto& seat = client_.seat();
  if (config_.seat_file.empty() || !seat) return;
  const client::SeatRecord record{seat->match, seat->seat, seat->token, client_.lastSequence()};
  if (auto error = client::writeSeatFile(config_.seat_file, record); !error.empty()) {
    spdlog::warn("seat file: {}", error);
  }
}

// ---- Playing ------------------------------------------------------------------------------------

void BotPlayer::onState(const client::MatchView& view, double now) {
  const auto& seat = client_.seat();
  if (!seat || view.match != seat->match || stage_ != BotStage::Playing) return;
  if (view.phase == client::MatchPhase::Over) {
    const auto& other = view.seats[static_cast<std::size_t>(1 - seat->seat)];
    if (config_.stay && !other.name.empty()) {
      askRematch(view);
    } else {
      finish(view);
    }
    return;
  }
  rematch_asked_ = false;
  // The server takes us for gone while we are here: our liveliness lease ran out while this
  // process was starved of CPU, or the server restarted and resumed the match before its old
  // self's lease ran out. Take the seat back with our token and key before the grace runs out
  // (once per state that shows us away).
  const client::SeatView& mine = view.seats[static_cast<std::size_t>(seat->seat)];
  if (mine.connected) {
    away_revision_.reset();
  } else if (mine.name == client_.name() && (!away_revision_ || view.revision != *away_revision_)) {
    away_revision_ = view.revision;
    loseSeat(now, "the server shows us away");
    sendJoin(now);
  }
}

void BotPlayer::onReport(const client::ShotReport& report, double now) {
  const auto& seat = client_.seat();
  if (!seat || !pending_seq_ || report.match != seat->match || report.seat != seat->seat ||
      report.seq != *pending_seq_) {
    return;
  }
  pending_seq_.reset();
  if (report.accepted) {
    rejections_ = 0;
    wait_for_shot_ = report.shot_number;
    // A choice without a stroke keeps the shot number: the next turn is on a newer state only
    // (acting again on the state it answered sent the choice twice, the second refused).
    blocked_revision_ = shot_revision_;
    return;
  }
  ++rejections_;
  spdlog::warn("shot {} rejected: {} ({})", report.seq, client::toString(report.reject_reason),
               report.reject_text);
  retry_at_ = now + std::min(kMaxRetryDelay, 0.05 * rejections_);
  using client::RejectReason;
  const auto r = report.reject_reason;
  if (r == RejectReason::NotYourTurn || r == RejectReason::BallsMoving ||
      r == RejectReason::MatchOver) {
    blocked_revision_ = shot_revision_;
  }
}

bool BotPlayer::myTurn(const client::MatchView& view) const {
  const auto& seat = client_.seat();
  return seat && client::inPlay(view.phase) && view.shooter == seat->seat &&
         view.shot_number >= wait_for_shot_ &&
         (!blocked_revision_ || view.revision > *blocked_revision_);
}

void BotPlayer::maybeShoot(double now) {
  const auto& seat = client_.seat();
  if (!seat) return;
  if (pending_seq_) {
    if (now - shot_sent_at_ < config_.answer_timeout) return;
    spdlog::warn("no answer to shot {} after {} s: sending again", *pending_seq_,
                 config_.answer_timeout);
    pending_seq_.reset();
  }
  const client::MatchView* view = client_.state(seat->match);
  if (!view || now < retry_at_ || !myTurn(*view)) return;
  if (concede_request_) return;  // no shot while the concession is on its way
  if (config_.concede_from_rack != 0 && view->rack >= config_.concede_from_rack) {
    // A rack to concede is never played on, not even on a state older than the concession.
    if (conceded_rack_ != view->rack) {
      conceded_rack_ = view->rack;
      spdlog::info("conceding rack {} of {}", view->rack, seat->match);
      concede_request_ = client_.requestConcede();
    }
    return;
  }
  if (turn_revision_ != view->revision) {
    turn_revision_ = view->revision;
    turn_since_ = now;
    clock_deadline_.reset();
    if (view->shot_clock >= 0.0) clock_deadline_ = now + view->shot_clock;
  }
  const bool pressed =
      clock_deadline_ && !config_.ignore_shot_clock && now >= *clock_deadline_ - kClockMargin;
  if (!tableFor(seat->match)) return;
  if (now - turn_since_ < config_.think && !pressed) {
    // Watchers see the cue swing onto the shot and draw back while the bot thinks.
    const PlannedShot& planned = planFor(*view);
    if (shoots(planned)) showAim(*view, planned, (now - turn_since_) / config_.think, false, now);
    return;
  }
  PlannedShot shot = planFor(*view);
  if (shoots(shot) && config_.think > 0.0 && stroke_revision_ != view->revision) {
    // The stroke goes out a pass before the command, so that it finds its turn still open.
    plan_->cue = played(plan_->cue);
    stroke_revision_ = view->revision;
    showAim(*view, *plan_, 1.0, true, now);
    return;
  }
  if (shoots(shot) && config_.think <= 0.0) shot.cue = played(shot.cue);
  plan_.reset();
  const auto sent = client_.shoot(requestOf(shot));
  if (!sent) {
    spdlog::warn("shot not sent: {}", sent.error());
    retry_at_ = now + kMaxRetryDelay;
    return;
  }
  spdlog::info("shot {} (state {}): {}", *sent, view->revision, describe(shot));
  pending_seq_ = *sent;
  shot_sent_at_ = now;
  shot_revision_ = view->revision;
  saveSeat();
}

const PlannedShot& BotPlayer::planFor(const client::MatchView& view) {
  if (!plan_ || plan_revision_ != view.revision) {
    // The game decides what is legal: the view's rules follow the match's settings.
    tables_[planner_table_]->rules.game = view.settings.game;
    tables_[planner_table_]->rules.three_cushion.points_to = view.settings.points;
    plan_ = planner_->plan(view.balls, client::gameStateOf(view));
    plan_revision_ = view.revision;
  }
  return *plan_;
}

physics::CueShot BotPlayer::played(const physics::CueShot& cue) {
  if (config_.skill) return noise_.apply(cue);
  return perturbed(cue, planner_options_.noise, level_rng_);
}

void BotPlayer::showAim(const client::MatchView& view, const PlannedShot& shot, double progress,
                        bool stroke, double now) {
  protocol::AimSample aim = thinkingAim(shot, view.balls, progress);
  aim.shot_number = view.shot_number;
  aim.stroke = stroke;
  if (!pacer_.due(aim, now)) return;
  if (auto sent = client_.sendAim(aim); !sent) spdlog::debug("aim not sent: {}", sent.error());
}

const TableView* BotPlayer::tableFor(const std::string& match) {
  const client::LobbyEntry* entry = client_.lobby().find(match);
  const std::string name = entry && !entry->table.empty() ? entry->table : kDefaultTable;
  auto& slot = tables_[name];
  if (!slot) {
    auto loaded = loadTableView(name);
    if (!loaded) {
      spdlog::error("{}", loaded.error());
      tables_.erase(name);
      return nullptr;
    }
    slot = std::make_unique<TableView>(std::move(*loaded));
  }
  if (planner_table_ != name) {
    planner_options_ =
        config_.skill ? PlannerOptions{} : plannerOptionsFor(config_.level, slot->radius());
    planner_ = std::make_unique<ShotPlanner>(*slot, planner_options_);
    planner_table_ = name;
  }
  return slot.get();
}

void BotPlayer::askRematch(const client::MatchView& view) {
  if (rematch_asked_) return;
  rematch_asked_ = true;
  spdlog::info("{}; staying: asked for a rematch", resultOf(view));
  client_.requestRematch();
}

std::string BotPlayer::resultOf(const client::MatchView& view) const {
  const int me = client_.seat()->seat;
  const int other = 1 - me;
  const bool won = view.winner == me;
  int mine = view.seats[static_cast<std::size_t>(me)].racks_won;
  int theirs = view.seats[static_cast<std::size_t>(other)].racks_won;
  if (mine + theirs == 0) (won ? mine : theirs) = 1;  // a one-rack match that counts no racks
  char line[160];
  std::snprintf(line, sizeof line, "result: %s %d-%d (%s after %u shots)", won ? "win" : "loss",
                mine, theirs, rules::toString(view.end), view.shot_number);
  return line;
}

void BotPlayer::finish(const client::MatchView& view) {
  result_line_ = resultOf(view);
  stage_ = BotStage::Finished;
  if (!config_.seat_file.empty()) {
    std::error_code ec;
    std::filesystem::remove(config_.seat_file, ec);
  }
}

}  // namespace pool::bot
