// The players' pages: each player's rating and statistics per game, in words, from the gateway's
// players message (one record per server, player key and game).

function plural(n, one, many) {
  return `${n} ${n === 1 ? one : many}`;
}

/** What a stroke scores: points in snooker and three-cushion, balls in pool. */
function scoreWord(game) {
  return game === 'three-cushion' || game === 'snooker' ? 'point' : 'ball';
}

/** One line for a player's list entry: "Ada at srv: 8-ball 1562, snooker 1500". */
export function playerButtonText(records) {
  const name = records[0].name || 'a player';
  const games = records.map((r) => `${r.game} ${r.rating}`).join(', ');
  return `${name} at ${records[0].server}: ${games}`;
}

/** A player's facts in one game, as lines. */
export function playerLines(r) {
  const word = scoreWord(r.game);
  const rackWord = r.game === 'snooker' ? 'frame' : r.game === 'three-cushion' ? 'game' : 'rack';
  // Balls (or points) an attempt: one stroke can pot two balls, so a share of the attempts could
  // pass 100 %.
  const share = r.attempts > 0 ? ` (${(r.pots / r.attempts).toFixed(2)} an attempt)` : '';
  const best = r.game === 'snooker' ? `highest break ${r.high_run}` : `best inning ${plural(r.high_run, word, `${word}s`)}`;
  return [
    `${r.game}: rating ${r.rating} ±${r.rating_deviation}`,
    `matches ${r.matches_won} won of ${r.matches}; ${rackWord}s ${r.racks_won} won of ${r.racks}`,
    `${plural(r.pots, word, `${word}s`)} from ${plural(r.attempts, 'attempt', 'attempts')}${share}; ${plural(r.strokes, 'stroke', 'strokes')} in all`,
    `${plural(r.breaks, 'break', 'breaks')}, ${plural(r.break_pots, word, `${word}s`)} on them; ${plural(r.break_and_runs, 'break-and-run', 'breaks-and-runs')}`,
    `${plural(r.fouls, 'foul', 'fouls')}, ${plural(r.safeties, 'safety', 'safeties')}; ${best}`,
  ];
}

/** The records grouped by player (server and key), in the order first seen. */
export function byPlayer(records) {
  const groups = new Map();
  for (const r of records) {
    const id = `${r.server}/${r.player}`;
    if (!groups.has(id)) groups.set(id, []);
    groups.get(id).push(r);
  }
  return groups;
}
