// Entering a tournament and playing its matches one after another.
#include "client/bot/tournament_entrant.h"

#include <spdlog/spdlog.h>

#include "core/hex.h"

namespace pool::bot {

TournamentEntrant::TournamentEntrant(client::GameClient& client, BotConfig config,
                                     std::string tournament)
    : client_(client), config_(std::move(config)), tournament_(std::move(tournament)) {}

int TournamentEntrant::me(const protocol::TournamentView& view) const {
  return view.entrantOf(hexOf(client_.key().public_key));
}

void TournamentEntrant::step(double now) {
  switch (stage_) {
    case Stage::Entering:
      enter(now);
      return;
    case Stage::Waiting:
      for (const auto& event : client_.poll()) (void)event;  // the client keeps the brackets
      wait();
      return;
    case Stage::Playing:
      player_->step(now);
      if (!player_->done()) return;
      if (player_->stage() == BotStage::Failed) {
        spdlog::warn("{}: {}", playing_, player_->failure());
      } else {
        spdlog::info("{}: {}", playing_, player_->resultLine());
        if (player_->resultLine().rfind("result: win", 0) == 0) ++won_;
      }
      played_.insert(playing_);
      player_.reset();
      stage_ = Stage::Waiting;
      return;
    case Stage::Done:
    case Stage::Failed:
      return;
  }
}

void TournamentEntrant::enter(double now) {
  for (const auto& event : client_.poll()) {
    const auto* answer = std::get_if<client::JoinAnswer>(&event);
    if (!answer || !request_ || answer->request != *request_) continue;
    request_.reset();
    if (answer->accepted()) {
      spdlog::info("entered {}", tournament_);
      stage_ = Stage::Waiting;
      return;
    }
    // A tournament not published yet (its server starting) is asked for again; any other
    // refusal is for good.
    if (answer->outcome != client::JoinOutcome::NoSuchMatch) {
      failure_ = "entering " + tournament_ + ": " + answer->reason;
      stage_ = Stage::Failed;
      return;
    }
  }
  if (now - sent_at_ >= config_.join_retry) {
    request_ = client_.requestEnter(tournament_);
    sent_at_ = now;
  }
}

void TournamentEntrant::wait() {
  const auto it = client_.tournaments().find(tournament_);
  if (it == client_.tournaments().end()) return;
  const protocol::TournamentView& view = it->second;
  const int mine = me(view);
  if (view.phase == protocol::TournamentPhase::Finished ||
      view.phase == protocol::TournamentPhase::Cancelled) {
    std::string how = "cancelled";
    if (view.phase == protocol::TournamentPhase::Finished) {
      how = view.champion == mine && mine >= 0
                ? std::string("champion")
                : "place " + std::to_string(mine >= 0 ? view.entrants[mine].place : 0);
    }
    result_line_ = "tournament " + tournament_ + " " + protocol::toString(view.phase) + ": " + how +
                   " (" + std::to_string(won_) + " match" + (won_ == 1 ? "" : "es") + " won)";
    stage_ = Stage::Done;
    return;
  }
  if (mine < 0) return;
  for (const auto& m : view.matches) {
    if (m.state != 2 || m.match.empty() || (m.a != mine && m.b != mine)) continue;
    if (played_.count(m.match)) continue;
    BotConfig config = config_;
    config.match = m.match;
    config.stay = false;
    playing_ = m.match;
    player_ = std::make_unique<BotPlayer>(client_, config, std::nullopt);
    spdlog::info("{} {}: playing at {}", tournament_, m.round, m.match);
    stage_ = Stage::Playing;
    return;
  }
}

}  // namespace pool::bot
