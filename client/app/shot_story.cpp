// Sentences for shots, fouls, choices and the end of a game.
#include "client/app/shot_story.h"

#include <cctype>
#include <cstddef>

#include "client/app/spoken.h"

namespace pool::app {
namespace {

std::string ballsSaid(const std::vector<int>& ids) {
  std::string out;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (i > 0) out += i + 1 == ids.size() ? " and " : ", ";
    out += "the " + std::to_string(ids[i]);
  }
  return out;
}

const std::string& nameOf(const SeatNames& names, int seat) {
  static const std::string kNobody = "nobody";
  return seat == 0 || seat == 1 ? names[static_cast<std::size_t>(seat)] : kNobody;
}

}  // namespace

SeatNames seatNames(const client::MatchView* view) {
  SeatNames names{"Player 1", "Player 2"};
  if (!view) return names;
  for (std::size_t s = 0; s < 2; ++s) {
    if (!view->seats[s].name.empty()) names[s] = view->seats[s].name;
  }
  return names;
}

std::string foulReason(rules::Foul foul) {
  switch (foul) {
    case rules::Foul::CueBallPocketed:
      return "the cue ball fell in a pocket (a scratch)";
    case rules::Foul::CueBallOffTable:
      return "the cue ball left the table";
    case rules::Foul::NoBallHit:
      return "the cue ball hit no ball";
    case rules::Foul::WrongBallFirst:
      return "the first ball hit was not one the shooter may hit first";
    case rules::Foul::NoCushionAfterContact:
      return "after the contact no ball fell and none reached a cushion";
    case rules::Foul::ObjectBallOffTable:
      return "a ball left the table";
    case rules::Foul::ShotClockExpired:
      return "the shot clock ran out";
    case rules::Foul::IllegalBreak:
      return "an illegal break: no ball fell and fewer than four reached a cushion";
    case rules::Foul::BehindHeadStringDirect:
      return "with the cue ball in hand behind the head string, a ball behind it was hit directly";
  }
  return "a foul";
}

std::string endReason(rules::GameEnd end) {
  switch (end) {
    case rules::GameEnd::None:
      return "the game goes on";
    case rules::GameEnd::EightPocketed:
      return "the 8 went in the called pocket";
    case rules::GameEnd::Forfeit:
      return "a forfeit";
    case rules::GameEnd::PointsReached:
      return "the points of the game reached";
    default:
      return spoken(rules::toString(end));
  }
}

std::string inHandWhere(rules::BallInHand in_hand) {
  switch (in_hand) {
    case rules::BallInHand::Anywhere:
      return "anywhere on the table";
    case rules::BallInHand::BehindHeadString:
      return "behind the head string (in the kitchen)";
    case rules::BallInHand::None:
      break;
  }
  return "";
}

std::string choiceSentence(rules::Choice choice, const std::string& other) {
  switch (choice) {
    case rules::Choice::PlayOn:
      return "Play on: take the table as it lies and shoot.";
    case rules::Choice::BallInHand:
      return "Take the cue ball in hand behind the head string and shoot.";
    case rules::Choice::RespotEight:
      return "Put the 8 back on its spot and shoot.";
    case rules::Choice::ReBreak:
      return "Rack the balls again and break yourself.";
    case rules::Choice::OpponentReBreaks:
      return "Rack the balls again and let " + other + " break.";
    case rules::Choice::PushOut:
      return "Play a push-out: move the cue ball anywhere without having to hit the lowest ball; " +
             other + " then chooses who shoots next.";
    case rules::Choice::PassBack:
      return "Pass the table back: " + other + " shoots from where the balls lie.";
  }
  return "";
}

std::string shotStory(const client::ShotReport& report, const SeatNames& names, rules::Game game) {
  const std::string& shooter = nameOf(names, report.seat);
  std::string out;
  if (!report.fouls.empty()) {
    out = "Foul by " + shooter + ": ";
    for (std::size_t i = 0; i < report.fouls.size(); ++i) {
      out += (i > 0 ? "; " : "") + foulReason(report.fouls[i]);
    }
    out += ".";
    if (!report.pocketed.empty()) out += " Down: " + ballsSaid(report.pocketed) + ".";
  } else if (game == rules::Game::ThreeCushion) {
    out = shooter + (report.scored > 0 ? " scored a point." : " made no point.");
  } else if (!report.pocketed.empty()) {
    out = shooter + " pocketed " + ballsSaid(report.pocketed) + ".";
  } else {
    out = shooter + " pocketed nothing.";
  }
  if (report.game_over) {
    return out + " Game over: " + nameOf(names, report.winner) + " wins (" + endReason(report.end) +
           ").";
  }
  const std::string& next = nameOf(names, report.next_shooter);
  if (report.turn_continues) {
    out += " " + shooter + " shoots again";
  } else {
    out += " " + next + " to shoot";
  }
  const std::string where = inHandWhere(report.ball_in_hand);
  out += where.empty() ? "." : ", with the cue ball in hand " + where + ".";
  if (!report.options.empty()) out += " " + next + " has a choice to make first.";
  return out;
}

std::string verdictInWords(const std::string& verdict, const SeatNames& names) {
  // The server's verdict numbers seats from 0 ("seat 1 to shoot" is the second player).
  // Names are put in afterwards so that a name never reads as a seat or an identifier.
  std::string text;
  std::size_t i = 0;
  while (i < verdict.size()) {
    const bool seat =
        verdict.compare(i, 5, "seat ") == 0 && i + 5 < verdict.size() &&
        (verdict[i + 5] == '0' || verdict[i + 5] == '1') &&
        (i + 6 == verdict.size() || !std::isdigit(static_cast<unsigned char>(verdict[i + 6])));
    if (!seat) {
      text += verdict[i++];
      continue;
    }
    text += verdict[i + 5] == '0' ? '\x01' : '\x02';
    i += 6;
  }
  text = spokenText(text);
  std::string out;
  for (const char c : text) {
    if (c == '\x01' || c == '\x02') {
      out += names[c == '\x01' ? 0 : 1];
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace pool::app
