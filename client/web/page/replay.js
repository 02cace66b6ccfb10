// A stored shot played again on the page (/?match=ID&shot=N): the gateway's replay message (its
// frames rebuilt from the stored layouts and events), handed to the same playback as live frames
// as their time comes, then the table at rest.

/** How long the table at rest stays before the shot starts, s (the page has just drawn it). */
export const REPLAY_LEAD = 0.6;

export class Replay {
  /** `message`: the gateway's replay message (found); `now`: seconds on the page's clock. */
  constructor(message, now) {
    this.message = message;
    this.start = now + REPLAY_LEAD;
    this.next = 0;
  }

  /** The frames due by `now`, as live frame messages ({shot, frame, t, balls}), each once. */
  due(now) {
    const out = [];
    const frames = this.message.frames;
    const t = now - this.start;
    while (this.next < frames.length && frames[this.next].t <= t) {
      const f = frames[this.next];
      out.push({ shot: this.message.shot, frame: this.next, t: f.t, balls: f.balls });
      ++this.next;
    }
    return out;
  }

  /** Every frame handed out. */
  handedOut() {
    return this.next >= this.message.frames.length;
  }

  /** Plays it again from its start. */
  again(now) {
    this.start = now + REPLAY_LEAD;
    this.next = 0;
  }

  /** The balls to draw when no frame is playing: the layout at the strike, or at rest. */
  still() {
    return this.next === 0 ? this.message.before : this.message.after;
  }
}

/** The page's link to stroke `shot` of `match`. */
export function replayLink(match, shot) {
  const url = new URL(window.location.href);
  url.search = '';
  url.searchParams.set('match', match);
  url.searchParams.set('shot', String(shot));
  return url.toString();
}

/** Lines for the side panel: who played it, what it was, what the referee said. */
export function replayLines(m) {
  const shooter = m.players[m.seat] || `seat ${m.seat + 1}`;
  return [
    `${m.players[0] || 'seat 1'} v ${m.players[1] || 'seat 2'}, ${m.game} on ${m.table}`,
    `Shot ${m.shot} of ${m.shots}, played by ${shooter}`,
    m.verdict_words ? `Verdict: ${m.verdict_words}` : '',
  ].filter((t) => t);
}
