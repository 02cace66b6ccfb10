// Runs the page's PlaybackClock (build/web/playback.js) over the steps in a JSON file and prints
// what it draws at each sample, for playback_parity_test.cpp to compare with the window's.
// Usage: node playback_parity.mjs PLAYBACK_JS STEPS_JSON
import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';

const { PlaybackClock } = await import(pathToFileURL(process.argv[2]).href);
const steps = JSON.parse(readFileSync(process.argv[3], 'utf8'));
const clock = new PlaybackClock();
const out = [];
for (const step of steps) {
  if (step.frame) {
    clock.push(step.frame, step.now);
  } else {
    const balls = clock.sample(step.now);
    out.push({ play: clock.play, balls, inMotion: clock.inMotion(step.settled) });
  }
}
process.stdout.write(JSON.stringify(out));
