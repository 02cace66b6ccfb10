// Sentences for shots, fouls, choices and the end of a game.
#include "client/app/shot_story.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstddef>

#include "client/app/scoreboard.h"
#include "client/app/spoken.h"
#include "rules/snooker.h"

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

std::string foulReason(rules::Foul foul, rules::Game game) {
  if (game == rules::Game::Snooker) {
    switch (foul) {
      case rules::Foul::NoBallHit:
        return "the cue ball hit no ball";
      case rules::Foul::WrongBallFirst:
        return "the first ball hit was not a ball on";
      case rules::Foul::ObjectBallOffTable:
        return "a ball left the table";
      default:
        break;
    }
  }
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
    case rules::Foul::BallNotOnPocketed:
      return "a ball not on fell";
    case rules::Foul::PushStroke:
      return "a push stroke: a ball touching the cue ball moved with it";
    case rules::Foul::JumpShot:
      return "a jump shot: the cue ball jumped over a ball";
    case rules::Foul::FreeBallSnookers:
      return "the free ball snookers the next player";
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
    case rules::GameEnd::FrameOver:
      return "the frame won on points";
    case rules::GameEnd::ThreeMisses:
      return "a third miss in a row with a ball on in plain view";
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
    case rules::BallInHand::InTheD:
      return "in the D";
    case rules::BallInHand::None:
      break;
  }
  return "";
}

std::string choiceSentence(rules::Choice choice, const std::string& other, rules::Game game) {
  if (game == rules::Game::Snooker) {
    switch (choice) {
      case rules::Choice::PlayOn:
        return "Play from here: take the table as it lies and shoot.";
      case rules::Choice::PassBack:
        return "Make " + other + " play again from where the balls lie.";
      default:
        break;
    }
  }
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
    case rules::Choice::FreeBall:
      return "Take a free ball: play from here, and the ball you nominate (or hit first) counts "
             "as the ball on.";
    case rules::Choice::Replace:
      return "Put the balls back as they were before the miss, and " + other + " plays again.";
  }
  return "";
}

std::string snookerBallsSaid(const std::vector<int>& ids) {
  static const std::array<const char*, 16> kCount{
      "no",    "a",    "two", "three",  "four",   "five",     "six",      "seven",
      "eight", "nine", "ten", "eleven", "twelve", "thirteen", "fourteen", "fifteen"};
  std::vector<std::string> parts;
  const auto reds = static_cast<std::size_t>(
      std::count_if(ids.begin(), ids.end(), [](int id) { return rules::isRed(id); }));
  if (reds > 0) {
    parts.push_back(std::string(kCount[std::min<std::size_t>(reds, 15)]) +
                    (reds == 1 ? " red" : " reds"));
  }
  for (const int id : ids) {
    if (!rules::isRed(id)) parts.push_back("the " + snookerBallName(id));
  }
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i > 0) out += i + 1 == parts.size() ? " and " : ", ";
    out += parts[i];
  }
  return out;
}

FoulPoints foulPointsOf(const std::string& verdict_text) {
  FoulPoints points;
  const std::size_t away = verdict_text.find(" away");
  if (away != std::string::npos) {
    std::size_t start = away;
    while (start > 0 && std::isdigit(static_cast<unsigned char>(verdict_text[start - 1]))) --start;
    if (start < away && away - start <= 3) {
      points.away = std::stoi(verdict_text.substr(start, away - start));
    }
  }
  points.miss = verdict_text.find("; a miss") != std::string::npos;
  return points;
}

namespace {

/// The snooker choices offered to `chooser` in short, e.g. "play from here, take a free ball or
/// make Ada play again".
std::string snookerChoicesSaid(const std::vector<rules::Choice>& options,
                               const std::string& offender) {
  std::vector<std::string> said;
  for (const rules::Choice c : options) {
    switch (c) {
      case rules::Choice::PlayOn:
        said.emplace_back("play from here");
        break;
      case rules::Choice::FreeBall:
        said.emplace_back("take a free ball");
        break;
      case rules::Choice::PassBack:
        said.push_back("make " + offender + " play again");
        break;
      case rules::Choice::Replace:
        said.push_back("put the balls back for " + offender + " to play again");
        break;
      default:
        said.emplace_back(spoken(rules::toString(c)));
        break;
    }
  }
  std::string out;
  for (std::size_t i = 0; i < said.size(); ++i) {
    if (i > 0) out += i + 1 == said.size() ? " or " : ", ";
    out += said[i];
  }
  return out;
}

std::string snookerStory(const client::ShotReport& report, const SeatNames& names) {
  const std::string& shooter = nameOf(names, report.seat);
  const std::string& next = nameOf(names, report.next_shooter);
  const std::string& other = nameOf(names, report.seat == 0 ? 1 : 0);
  const FoulPoints points = foulPointsOf(report.verdict_text);
  std::string out;
  if (!report.fouls.empty()) {
    out = std::string(points.miss ? "Foul and a miss by " : "Foul by ") + shooter + ": ";
    for (std::size_t i = 0; i < report.fouls.size(); ++i) {
      out += (i > 0 ? "; " : "") + foulReason(report.fouls[i], rules::Game::Snooker);
    }
    if (points.away > 0) out += "; " + std::to_string(points.away) + " away to " + other;
    out += ".";
    if (!report.pocketed.empty()) out += " Down: " + snookerBallsSaid(report.pocketed) + ".";
  } else if (report.events.empty() && !report.game_over) {
    // A choice without a stroke (play again, the balls put back).
    return shooter + " had " + next + " play again" +
           (report.next_shooter == report.seat ? "" : " (" + next + " to shoot)") + ".";
  } else if (!report.pocketed.empty()) {
    out = shooter + " potted " + snookerBallsSaid(report.pocketed) + ": " +
          std::to_string(report.scored) + (report.scored == 1 ? " point." : " points.");
  } else {
    out = shooter + " potted nothing.";
  }
  if (report.game_over) {
    return out + " Frame over: " + nameOf(names, report.winner) + " wins it (" +
           endReason(report.end) + ").";
  }
  out += report.turn_continues ? " " + shooter + " plays on" : " " + next + " to shoot";
  const std::string where = inHandWhere(report.ball_in_hand);
  out += where.empty() ? "." : ", with the cue ball in hand " + where + ".";
  if (!report.options.empty()) {
    out += " " + next + " chooses: " + snookerChoicesSaid(report.options, shooter) + ".";
  }
  return out;
}

}  // namespace

std::string shotStory(const client::ShotReport& report, const SeatNames& names, rules::Game game) {
  if (game == rules::Game::Snooker) return snookerStory(report, names);
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
