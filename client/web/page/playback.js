// Smooth playback of a shot's frames, by the game window's rules (client/net/snapshot_buffer,
// client/app/playback_clock): 0.1 s behind the earliest arrival, positions interpolated linearly
// and orientations spherically, never back in time, catching up gently, a lag past 0.5 s jumped.

/** The window's playback settings (PlaybackConfig). */
export const PLAYBACK = { delay: 0.1, maxSkew: 0.05, resync: 0.5, capacity: 32 };

/** A frame's ball: [id, x, y, z, qw, qx, qy, qz, onTable]. Orientations (indices 4..7) are
 * blended as Eigen's Quaternion::slerp does, the shorter way round, so the page turns a ball
 * exactly as the window does. */
function slerp(a, b, u) {
  const d = a[4] * b[4] + a[5] * b[5] + a[6] * b[6] + a[7] * b[7];
  const absD = Math.abs(d);
  let scale0 = 1 - u;
  let scale1 = u;
  if (absD < 1 - Number.EPSILON) {
    const theta = Math.acos(absD);
    const sinTheta = Math.sin(theta);
    scale0 = Math.sin((1 - u) * theta) / sinTheta;
    scale1 = Math.sin(u * theta) / sinTheta;
  }
  if (d < 0) scale1 = -scale1;
  return [0, 1, 2, 3].map((i) => scale0 * a[4 + i] + scale1 * b[4 + i]);
}

function blend(fa, fb, t) {
  const span = fb.t - fa.t;
  const u = span > 0 ? Math.min(Math.max((t - fa.t) / span, 0), 1) : 1;
  return fa.balls.map((a) => {
    const b = fb.balls.find((o) => o[0] === a[0]);
    if (!b) return a;
    const q = slerp(a, b, u);
    return [a[0], (1 - u) * a[1] + u * b[1], (1 - u) * a[2] + u * b[2], (1 - u) * a[3] + u * b[3],
      q[0], q[1], q[2], q[3], a[8]];
  });
}

/** The latest frames of the shot in motion, oldest first (SnapshotBuffer). */
export class SnapshotBuffer {
  constructor(capacity = 8) {
    this.capacity = capacity;
    this.frames = [];
  }

  /** False when dropped: a frame of an older shot, or not newer than the newest of its shot. */
  push(frame) {
    const newest = this.latest();
    if (newest) {
      if (frame.shot > newest.shot) this.frames = [];
      else if (frame.shot < newest.shot || frame.frame <= newest.frame) return false;
    }
    this.frames.push(frame);
    while (this.frames.length > this.capacity) this.frames.shift();
    return true;
  }

  /** The balls at simulated time t, or null when empty. */
  sample(t) {
    const f = this.frames;
    if (!f.length) return null;
    if (t <= f[0].t) return f[0].balls;
    for (let i = 1; i < f.length; ++i) {
      if (t <= f[i].t) return blend(f[i - 1], f[i], t);
    }
    return f[f.length - 1].balls;
  }

  latest() {
    return this.frames.length ? this.frames[this.frames.length - 1] : null;
  }

  clear() {
    this.frames = [];
  }
}

/** One match's shot in motion as drawn; `now` in seconds on a steady clock (PlaybackClock). */
export class PlaybackClock {
  constructor(config = PLAYBACK) {
    this.config = config;
    this.buffer = new SnapshotBuffer(config.capacity);
    this.targetOffset = 0;
    this.offset = 0;
    this.play = 0;
    this.lastNow = 0;
    this.started = false;
  }

  push(frame, now) {
    const arrivalOffset = now - frame.t;
    const latest = this.buffer.latest();
    const newShot = !latest || frame.shot > latest.shot;
    if (!this.buffer.push(frame)) return;
    if (newShot || !this.started) {
      this.targetOffset = this.offset = arrivalOffset;
      this.play = now - this.offset - this.config.delay;
      this.lastNow = now;
      this.started = true;
      return;
    }
    this.targetOffset = Math.min(this.targetOffset, arrivalOffset);
  }

  sample(now) {
    if (!this.started) return null;
    const dt = Math.max(0, now - this.lastNow);
    this.lastNow = now;
    const gap = this.targetOffset - this.offset;
    const step = this.config.maxSkew * dt;
    this.offset = Math.abs(gap) > this.config.resync ? this.targetOffset
      : this.offset + Math.min(Math.max(gap, -step), step);
    this.play = Math.max(this.play, now - this.offset - this.config.delay);
    return this.buffer.sample(this.play);
  }

  shot() {
    const latest = this.buffer.latest();
    return latest ? latest.shot : null;
  }

  caughtUp() {
    const latest = this.buffer.latest();
    return !!latest && this.play >= latest.t;
  }

  /** Still to be drawn: not caught up, or the state counts fewer shots than the one playing. */
  inMotion(settledShots) {
    const playing = this.shot();
    return playing !== null && (!this.caughtUp() || settledShots < playing);
  }

  clear() {
    this.buffer.clear();
    this.started = false;
    this.play = 0;
  }
}
