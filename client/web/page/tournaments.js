// The tournaments of the page: each one's line in the lobby, and its bracket page
// (?tournament=ID): the entrants by seed with their places, and every match with its result or
// the table it is played at.

const FORMATS = { single: 'single elimination', double: 'double elimination',
  'round-robin': 'round robin' };

/** The lobby's line of tournament `t`. */
export function tournamentButtonText(t) {
  const entered = t.entrants.length;
  let where = `${entered}/${t.capacity} entered`;
  if (t.phase === 'running') {
    const decided = t.matches.filter((m) => m.state === 3).length;
    where = `running, ${decided} of ${t.matches.length} matches played`;
  } else if (t.phase === 'finished') {
    where = `won by ${t.champion >= 0 ? t.entrants[t.champion].name : '?'}`;
  } else if (t.phase === 'cancelled') {
    where = 'cancelled';
  }
  const handicap = t.handicap ? ', handicapped' : '';
  return `${t.name}: ${t.game}, ${FORMATS[t.format] || t.format}, race to ${t.race_to}${handicap} - ${where}`;
}

function nameOf(t, i) {
  return i >= 0 && i < t.entrants.length ? t.entrants[i].name : 'to come';
}

/** One line per match of the bracket: "QF: ann v hal - ann 1-0", "QF: ann v hal (hal +2) - in
 * play at srv-2". */
export function bracketLines(t) {
  return t.matches.map((m) => {
    let pair = `${m.round}: ${nameOf(t, m.a)} v ${nameOf(t, m.b)}`;
    // A handicap: the racks one of them started with.
    if (m.spot_a > 0) pair += ` (${nameOf(t, m.a)} +${m.spot_a})`;
    if (m.spot_b > 0) pair += ` (${nameOf(t, m.b)} +${m.spot_b})`;
    if (m.state === 3) {
      const score = m.forfeit ? 'by forfeit' : `${Math.max(m.racks_a, m.racks_b)}-${Math.min(m.racks_a, m.racks_b)}`;
      return { text: `${pair} - ${nameOf(t, m.winner)} won ${score}`, match: m.match, state: 3 };
    }
    if (m.state === 2) return { text: `${pair} - in play at ${m.match}`, match: m.match, state: 2 };
    return { text: `${pair} - ${m.state === 1 ? 'next' : 'waiting'}`, match: '', state: m.state };
  });
}

/** The entrants by seed (or entry order before the draw), with their places once known. */
export function entrantLines(t) {
  const order = t.entrants.map((e, i) => i);
  if (t.entrants.some((e) => e.seed > 0)) order.sort((a, b) => t.entrants[a].seed - t.entrants[b].seed);
  return order.map((i) => {
    const e = t.entrants[i];
    const seed = e.seed > 0 ? `${e.seed}. ` : '';
    const place = e.place > 0 && t.phase === 'finished' ? `, place ${e.place}` : '';
    return `${seed}${e.name} (${e.rating})${place}${e.withdrawn ? ', withdrawn' : ''}`;
  });
}
