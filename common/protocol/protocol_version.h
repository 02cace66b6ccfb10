// The protocol version of this build, readable without the generated wire types.
#pragma once

namespace pool::protocol {

/// pool.idl's PROTOCOL_VERSION (net/messages.h checks that the two agree). 3: one signed envelope
/// for every player message, signed seat requests. 4: every sample the server publishes is signed
/// by the server's key; 9-ball and 10-ball, match settings (game, race, breaks, shot clock) chosen
/// by whoever opens a table. 5: each match's states, results and frames travel in a DDS partition
/// of the match's own (an older client, listening in the default partition, would see none);
/// practice tables (the practice setting, PracticeCommand, the practice fields of MatchInfo and
/// MatchState); a seat may concede its rack (JOIN_CONCEDE); the shooter's live aim
/// (AimCommand in, CueAim relayed by the server). 6: JoinRequest has no key (a client's presence
/// is its writer's, so client ids anyone invents cost the server no instance). 7: three-cushion
/// (the game on the wire as 3, its points setting, each seat's points, innings and high run, the
/// run and the ball the shooter strikes), up to 22 balls a table (a snooker set). 8: snooker
/// (ball ids to 21, the game as 22, the ball on, free balls, misses, the cue ball in hand in the
/// D, a ball nominated without a pocket). 9: snooker's jump-shot and free-ball-snookers fouls; the
/// lobby's rack, shot count and game score (MatchInfo); players' records (PlayerStats); practice
/// tables of every game (practice commands of up to 22 balls). 10: a match's stored shots for
/// replays (HistoryRequest, HistoryShot); tournaments (JOIN_ENTER, TournamentInfo). 11: players
/// open tournaments (JOIN_ENTER with the match "new" and the tournament's format, entrants and
/// handicap); handicapped tournaments (each match's racks on the wire, who opened it).
inline constexpr unsigned kProtocolVersion = 11;

}  // namespace pool::protocol
