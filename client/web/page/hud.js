// The HUD's facts in plain words: the players, whose turn, groups, the score of the race (a
// snooker frame's scoreboard), what happened on the last shot, from the gateway's messages.

const GROUP = { solids: 'solids', stripes: 'stripes' };

function nameOf(state, seat) {
  const s = state.seats[seat];
  return s && s.name ? s.name : `seat ${seat + 1} (free)`;
}

function sentence(text) {
  if (!text) return '';
  const t = text.charAt(0).toUpperCase() + text.slice(1);
  return /[.!?]$/.test(t) ? t : `${t}.`;
}

function plural(n, one, many) {
  return `${n} ${n === 1 ? one : many}`;
}

/**
 * A snooker frame's scoreboard: the frame score and the frames won in the race, the break and
 * each player's highest, the ball on, reds left and points remaining, and who needs snookers.
 * `state.snooker` is the gateway's snooker object (web_json's stateJson: ball_on in words,
 * reds_left, points_remaining, snookers_required per seat, from the rules).
 */
function snookerFacts(state, facts) {
  const a = nameOf(state, 0);
  const b = nameOf(state, 1);
  const seats = state.seats;
  const board = state.snooker || {};
  facts.score = `Frame ${state.rack}: ${a} ${seats[0].points}, ${b} ${seats[1].points}.` +
    ` Frames won: ${a} ${seats[0].racks_won}, ${b} ${seats[1].racks_won}` +
    ` (race to ${plural(state.race_to, 'frame', 'frames')}).`;
  const shooter = state.shooter >= 0 ? nameOf(state, state.shooter) : null;
  const inPlay = ['break', 'open', 'assigned'].includes(state.phase);
  facts.breaks = (inPlay && shooter && state.run > 0 ? `${shooter}'s break: ${state.run}. ` : '') +
    `Highest breaks: ${a} ${seats[0].high_run}, ${b} ${seats[1].high_run}.`;
  if (inPlay && shooter) {
    const hand = state.ball_in_hand === 'in_the_d' ? ', with the cue ball in hand in the D' : '';
    facts.turn = `${shooter} to play, ${board.ball_on || 'on a red'}${hand}.`;
  }
  if (inPlay && typeof board.reds_left === 'number') {
    const needs = (board.snookers_required || []).map((n, i) => (n > 0
      ? ` ${nameOf(state, i)} needs snookers: ${plural(n, 'point', 'points')} short.` : ''));
    facts.groups = `${plural(board.reds_left, 'red', 'reds')} left,` +
      ` ${board.points_remaining} points remaining.${needs.join('')}`;
  } else {
    facts.groups = '';
  }
}

/**
 * The facts of a match: {title, players, score, breaks, turn, groups, last}. `state` is the
 * spectator's match_state object (with `snooker`, the gateway's snooker facts, in a snooker
 * match), `settings` its one-line settings, `result` the latest final shot result (or null),
 * `entry` the lobby entry (or null). `state.words` and `result.words`: their verdicts in words.
 */
export function describe(state, settings, result, entry) {
  const a = nameOf(state, 0);
  const b = nameOf(state, 1);
  const facts = {};
  facts.title = `${a} vs ${b}`;
  facts.players = `${a} against ${b}${settings ? `: ${settings}` : ''}`;
  const raceTo = entry ? entry.race_to : null;
  if (state.game === 'three-cushion') {
    // A carom score: points (first to points_to), innings and the high run of each player.
    const line = (i) => `${nameOf(state, i)} ${state.seats[i].points}` +
      ` (${state.seats[i].innings} inning${state.seats[i].innings === 1 ? '' : 's'},` +
      ` high run ${state.seats[i].high_run})`;
    facts.score = `Points: ${line(0)}, ${line(1)} (first to ${state.points_to} wins)` +
      (state.run > 0 ? `; run ${state.run}` : '');
  } else {
    facts.score = `Racks won: ${a} ${state.seats[0].racks_won}, ${b} ${state.seats[1].racks_won}` +
      (raceTo ? ` (first to ${raceTo} wins)` : '');
  }
  const shooter = state.shooter >= 0 ? nameOf(state, state.shooter) : null;
  switch (state.phase) {
    case 'lobby':
      facts.turn = 'Waiting for players to sit down.';
      break;
    case 'over':
      facts.turn = state.winner >= 0 ? `${nameOf(state, state.winner)} won the match.`
        : 'The match is over.';
      break;
    case 'closed':
      facts.turn = 'The match was closed.';
      break;
    default: {
      if (!shooter) {
        facts.turn = 'Waiting for the next shot.';
      } else if (state.game === 'three-cushion') {
        const ball = state.cue_ball === 1 ? 'yellow' : 'white';
        facts.turn = state.phase === 'break' ? `${shooter} to open with the ${ball}, red first.`
          : `${shooter} to shoot the ${ball}.`;
      } else if (state.phase === 'break') {
        facts.turn = `${shooter} to break (rack ${state.rack + 1}).`;
      } else if (state.ball_in_hand === 'anywhere') {
        facts.turn = `${shooter} to shoot, with the cue ball in hand anywhere on the table.`;
      } else if (state.ball_in_hand === 'behind_head_string') {
        facts.turn = `${shooter} to shoot, with the cue ball in hand behind the head string.`;
      } else {
        facts.turn = `${shooter} to shoot.`;
      }
    }
  }
  const groups = state.seats.map((s, i) => {
    const g = GROUP[s.group];
    const fouls = s.fouls ? `, ${s.fouls} foul${s.fouls === 1 ? '' : 's'}` : '';
    return g ? `${nameOf(state, i)} has the ${g}, ${s.balls_left} left${fouls}` : null;
  });
  facts.groups = state.game === 'three-cushion' ? '' : groups.every((g) => g === null)
    ? (state.phase === 'open' || state.phase === 'break' ? 'Open table: no groups yet.' : '')
    : `${groups.filter((g) => g).join('; ')}.`;
  // The verdict as the game's HUD words it, each "seat N" named.
  if (state.game === 'snooker') snookerFacts(state, facts);
  const words = state.words || (result ? result.words : '');
  const named = (words || '').replace(/\bseat ([01])\b/g, (_, n) => nameOf(state, Number(n)));
  facts.last = named ? `Last shot: ${sentence(named)}` : 'No shot played yet.';
  return facts;
}

/** A lobby entry in words: "Alice vs Bob, 8-ball, race to 1 (in play)". */
export function describeEntry(entry) {
  const ratings = entry.ratings || [0, 0];
  const player = (seat) => {
    const name = entry.players[seat];
    if (!name) return 'a free seat';
    return ratings[seat] > 0 ? `${name} (${ratings[seat]})` : name;
  };
  const [a, b] = entry.players;
  const who = a || b ? `${player(0)} vs ${player(1)}` : 'a free table';
  const phase = entry.in_play ? 'in play' : entry.phase === 'over' ? 'over' : 'waiting';
  const progress = entryProgress(entry);
  return `${who}, ${entry.settings}${progress ? `, ${progress}` : ''} (${phase})`;
}

/**
 * How far a match has gone, in the window lobby's words (client/app/lobby_line.cpp): "racks 2-1,
 * rack 4, shot 37", "frames 1-0, frame 2 45-12, shot 37"; "practice, shot 12"; '' before it starts.
 */
export function entryProgress(entry) {
  const shots = `shot ${entry.shot_number || 0}`;
  if (entry.practice) return `practice, ${shots}`;
  if (!entry.rack) return '';
  const word = entry.game === 'snooker' ? 'frame' : entry.game === 'three-cushion' ? 'game' : 'rack';
  const pair = (two) => `${two[0]}-${two[1]}`;
  let text = `${word}s ${pair(entry.racks_won)}, ${word} ${entry.rack}`;
  if (entry.game === 'snooker' || entry.game === 'three-cushion') text += ` ${pair(entry.rack_points)}`;
  return `${text}, ${shots}`;
}
