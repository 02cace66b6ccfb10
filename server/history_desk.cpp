// Answering a history request: the checks, the asker's share, then the stored strokes.
#include "server/history_desk.h"

#include "core/hex.h"
#include "rules/game_rules.h"

namespace pool::server {

std::vector<protocol::HistoryShot> HistoryDesk::answer(const net::IncomingHistory& in, double now,
                                                       std::string* why) {
  auto refuse = [&](std::string reason, std::uint64_t& counter) {
    ++counter;
    if (why) *why = std::move(reason);
    return std::vector<protocol::HistoryShot>{};
  };
  // The participant's share first (the cheapest check), then the request itself, then the key's
  // share and the server's whole budget (participants cost nothing).
  if (!by_sender_.allow(in.sender, now)) {
    return refuse("history requests: over the share of " + in.sender, counts_.limited);
  }
  if (!in.request) return refuse(in.request.error(), counts_.refused);
  const protocol::HistoryRequest& r = *in.request;
  if (auto ok = protocol::checkHistoryRequest(r); !ok) return refuse(ok.error(), counts_.refused);
  if (protocol::verifyHistory(r) != protocol::SignatureCheck::Valid) {
    return refuse("history request: not signed by the key it carries", counts_.refused);
  }
  if (!by_key_.allow(hexOf(r.public_key), now)) {
    return refuse("history requests: over the share of key " + hexOf(r.public_key).substr(0, 16),
                  counts_.limited);
  }
  if (!all_.allow("all", now)) {
    return refuse("history requests: over the server's budget", counts_.limited);
  }
  ++counts_.answered;
  protocol::HistoryShot head;
  head.client = r.client;
  head.request = r.request;
  head.asker = r.public_key;
  head.match = r.match;
  auto notFound = [&](std::string error) {
    head.found = false;
    head.error = std::move(error);
    return std::vector<protocol::HistoryShot>{head};
  };
  // Another server's match, or none: the request names an id this server never stored.
  if (r.match.rfind(server_ + "-", 0) != 0) return notFound("not a match of server " + server_);
  const auto match = store_.header(r.match);
  if (!match) return notFound("no match " + r.match + " is stored");
  head.shots = store_.strokes(r.match);
  head.game = match->settings.game;
  head.table = store_.tableOf(r.match);
  head.players = match->players;
  std::vector<protocol::HistoryShot> out;
  for (std::uint32_t n = r.first_shot; n < r.first_shot + r.count && n <= head.shots; ++n) {
    if (in_motion_ && in_motion_(r.match, n)) {
      if (out.empty())
        return notFound("shot " + std::to_string(n) + " of " + r.match + " is still being played");
      break;
    }
    const auto stored = store_.stroke(r.match, n);
    if (!stored) continue;
    protocol::HistoryShot shot = head;
    shot.found = true;
    shot.shot_number = n;
    shot.seat = stored->record.command.seat;
    shot.cue = stored->record.command.cue;
    shot.shoots = stored->record.shoots;
    shot.before = stored->record.before;
    shot.events = stored->record.events;
    shot.after = stored->record.after;
    shot.verdict_text = stored->verdict_text;
    out.push_back(std::move(shot));
  }
  if (out.empty()) {
    return notFound("match " + r.match + " has " + std::to_string(head.shots) + " shot" +
                    (head.shots == 1 ? "" : "s") + ": no shot " + std::to_string(r.first_shot));
  }
  return out;
}

}  // namespace pool::server
