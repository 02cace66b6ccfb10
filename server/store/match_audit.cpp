// The audit: the stored log judged again, compared field by field through its stored JSON form.
#include "server/store/match_audit.h"

#include "server/store/record_json.h"

namespace pool::store {

namespace {

void judgeAgain(const StoredShot& stored, const game::LoadedTable& kit,
                const rules::GameRules& rules, Audit& audit) {
  const server::ShotRecord& r = stored.record;
  const std::string at = "shot " + std::to_string(r.shot_number) + ": ";
  const rules::Shot shot{r.before, r.intent, r.events, r.after, false};
  const auto verdict = rules::judgeShot(rules, r.state, shot, kit.context);
  if (!verdict) {
    audit.problems.push_back(at + "the rules refuse it now: " + verdict.error());
    return;
  }
  if (verdictJson(*verdict) != verdictJson(r.verdict)) {
    audit.problems.push_back(at + "re-judged '" + rules::describe(*verdict) + "', stored '" +
                             rules::describe(r.verdict) + "'");
  }
  if (rules::describe(*verdict) != stored.verdict_text) {
    audit.problems.push_back(at + "stored text '" + stored.verdict_text + "' is not its verdict's");
  }
  audit.winner = verdict->game_over ? verdict->winner : -1;
  if (verdict->game_over && verdict->winner >= 0) {
    ++audit.racks[static_cast<std::size_t>(verdict->winner)];
  }
}

}  // namespace

Audit auditMatch(MatchStore& store, const std::string& id, const game::LoadedTable& kit,
                 const rules::EightBallConfig& rules) {
  Audit audit;
  const auto match = store.match(id);
  if (!match) {
    audit.problems.push_back("no stored match " + id);
    return audit;
  }
  for (const auto& stored : store.shots(id)) {
    if (!stored.record.shoots) {
      ++audit.choices;
      // A shot clock expiry (no command of a player) is judged like a shot without a strike.
      if (stored.record.command.seq == 0) {
        const server::ShotRecord& r = stored.record;
        const rules::Shot shot{r.before, r.intent, {}, r.after, true};
        const auto verdict = rules::judgeShot(
            {match->settings.game, rules, {match->settings.points}}, r.state, shot, kit.context);
        if (!verdict || verdictJson(*verdict) != verdictJson(r.verdict)) {
          audit.problems.push_back("a shot clock expiry after shot " +
                                   std::to_string(r.shot_number) + " re-judges otherwise");
        } else if (verdict->game_over && verdict->winner >= 0) {
          audit.winner = verdict->winner;
          ++audit.racks[static_cast<std::size_t>(verdict->winner)];
        }
      }
      continue;
    }
    if (stored.record.shot_number != audit.shots + 1) {
      audit.problems.push_back("shot " + std::to_string(stored.record.shot_number) +
                               " stored after shot " + std::to_string(audit.shots));
    }
    audit.shots = stored.record.shot_number;
    judgeAgain(stored, kit, {match->settings.game, rules, {match->settings.points}}, audit);
  }
  if (match->shot_number != audit.shots) {
    audit.problems.push_back("the match counts " + std::to_string(match->shot_number) + " shots, " +
                             std::to_string(audit.shots) + " are stored");
  }
  const bool over = match->game.phase == rules::Phase::Over;
  if (over && match->game.end != rules::GameEnd::Forfeit && match->game.winner != audit.winner) {
    audit.problems.push_back("the match's winner is seat " + std::to_string(match->game.winner) +
                             ", the shots give seat " + std::to_string(audit.winner));
  }
  return audit;
}

}  // namespace pool::store
