// The match's requests at the window, each carried out on the session with a note for the player.
#include "client/ui/window_match_desk.h"

#include "client/app/tournament_call.h"

#include <algorithm>

namespace pool::ui {

MatchDesk::MatchDesk(app::MatchSession& session, app::Controls& controls, TurnDesk& turn,
                     WindowNotes& notes, std::uint32_t domain)
    : session_(session), controls_(controls), turn_(turn), notes_(notes), domain_(domain) {}

void MatchDesk::newGame() {
  controls_.stopAiming();
  turn_.reset();
  in_room_ = false;
  session_.leave();
  session_.play();
  notes_.add({"looking for a free table for a new game", false});
}

void MatchDesk::rematch() {
  const client::MatchView* v = session_.view();
  if (!v) return;
  const auto local = session_.localSeats();
  for (int s = 0; s < 2; ++s) {
    const auto& seat = v->seats[static_cast<std::size_t>(s)];
    const bool ours = std::find(local.begin(), local.end(), s) != local.end();
    if (!ours && (seat.name.empty() || !seat.connected)) {
      notes_.add({session_.names()[static_cast<std::size_t>(s)] +
                      " has left the table: no rematch. N starts a new game at a free table.",
                  true});
      return;
    }
  }
  session_.rematch();
  notes_.add({"rematch asked", false});
}

void MatchDesk::startReplay(double speed, double now) {
  if (session_.inMotion()) {
    notes_.add({"the balls are moving: the replay waits for them to stop", false});
    return;
  }
  if (!session_.replay().start(now, speed)) {
    notes_.add({"no shot to replay yet", false});
    return;
  }
  notes_.add({"replaying shot " + std::to_string(*session_.replay().shot()), false});
}

bool MatchDesk::canConcede() const {
  const client::MatchView* v = session_.view();
  return v && client::inPlay(v->phase) && session_.stage() == app::SessionStage::Playing &&
         !session_.practiceTable() && !session_.localSeats().empty() && !session_.inMotion();
}

void MatchDesk::dropStaleQuestion() {
  if (concede_asked_ && !canConcede()) concede_asked_ = false;
}

void MatchDesk::answerConcede(bool yes) {
  concede_asked_ = false;
  if (!yes) return;
  if (!canConcede() || !session_.concede()) {
    notes_.add({"no rack to concede now", true});
    return;
  }
  controls_.stopAiming();
  turn_.end();
  notes_.add({"concession sent", false});
}

void MatchDesk::playPractice() {
  table_options_.practice = true;
  session_.setTableSettings(table_options_.settings());
  session_.play("new");
}

void MatchDesk::playBot(bot::Level level) {
  table_options_.practice = false;
  session_.setTableSettings(table_options_.settings());
  session_.play("new");
  bot_wanted_ = level;
  notes_.add({"a table for you and the " + botOpponentName(level) + "...", false});
}

void MatchDesk::startBotOpponent() {
  if (!bot_wanted_) return;
  if (session_.stage() == app::SessionStage::Lobby) bot_wanted_.reset();  // the player cancelled
  if (!bot_wanted_ || session_.stage() != app::SessionStage::Playing) return;
  const auto started = bot_opponent_.start(domain_, session_.match(), *bot_wanted_);
  notes_.add({started ? "the " + botOpponentName(*bot_wanted_) + " is coming to the table"
                      : started.error(),
              !started});
  bot_wanted_.reset();
}

void MatchDesk::takeLobbyChoice(const LobbyChoice& choice) {
  switch (choice.kind) {
    case LobbyChoice::Kind::Play:
      session_.setTableSettings(table_options_.settings());
      session_.play(choice.match);
      break;
    case LobbyChoice::Kind::PlayBot:
      playBot(static_cast<bot::Level>(table_options_.bot_level));
      break;
    case LobbyChoice::Kind::Spectate:
      session_.spectate(choice.match);
      break;
    case LobbyChoice::Kind::Cancel:
      session_.leave();
      break;
    case LobbyChoice::Kind::Replay:
      session_.showStored(choice.match);  // its last shot first
      break;
    case LobbyChoice::Kind::Enter:
      session_.enterTournament(choice.match);
      break;
    case LobbyChoice::Kind::AddBot:
      addTournamentBot(choice.match, static_cast<bot::Level>(table_options_.bot_level));
      break;
    case LobbyChoice::Kind::OpenTournament:
      session_.openTournament(table_options_.settings(), table_options_.opening());
      break;
  }
}

void MatchDesk::addTournamentBot(const std::string& tournament, bot::Level level) {
  // Bots started here play while the window stays (each its own key and DDS participant).
  std::erase_if(entrant_bots_, [](const auto& bot) { return !bot->running(); });
  if (entrant_bots_.size() >= kMaxEntrantBots) {
    notes_.add({"at most " + std::to_string(kMaxEntrantBots) + " bots from this window", true});
    return;
  }
  const std::string name = botOpponentName(level) + " " + std::to_string(++bots_named_);
  auto bot = std::make_unique<BotOpponent>();
  const auto started = bot->enter(domain_, tournament, level, name);
  notes_.add({started ? name + " is entering " + tournament : started.error(), !started});
  if (started) entrant_bots_.push_back(std::move(bot));
}

void MatchDesk::answerTournamentCall() {
  const auto call = app::tournamentCall(session_.tournaments(), session_.playerKey(), called_);
  if (!call) return;
  // From the lobby, or a decided match (the result on screen), the window goes to the table; a
  // player in the middle of a game (or a practice table) is told once, and goes when they like.
  const client::MatchView* v = session_.view();
  const bool decided = session_.stage() == app::SessionStage::Playing && v &&
                       v->phase == client::MatchPhase::Over && !session_.practiceTable();
  if (session_.stage() != app::SessionStage::Lobby && !decided) {
    if (told_.insert(call->match).second) {
      notes_.add({"your tournament match is ready at " + call->match + " (" + call->round + " v " +
                      call->opponent + "): leave this table to take it",
                  true});
    }
    return;
  }
  called_.insert(call->match);
  notes_.add(
      {"your tournament match: " + call->round + " v " + call->opponent + " at " + call->match,
       false});
  if (decided) session_.leave();
  session_.play(call->match);
}

}  // namespace pool::ui
