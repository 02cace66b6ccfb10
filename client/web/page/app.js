// The web spectator: connects to the gateway's WebSocket, shows the lobby, follows the chosen
// match (late join: the table, the latest state and result at once) and draws it with three.js,
// in the full or the light mode (look.js).
import * as THREE from './three.module.js';
import { PlaybackClock } from './playback.js';
import { buildTable, placeBalls, fitCamera, reflect } from './table.js';
import { dressTable } from './hall.js';
import { chooseMode, makeRenderer, environmentOf, softwareGl } from './look.js';
import { describe, describeEntry } from './hud.js';
import { byPlayer, playerButtonText, playerLines } from './players.js';
import { Replay, replayLink, replayLines } from './replay.js';
import { bracketLines, entrantLines, tournamentButtonText } from './tournaments.js';

const canvas = document.getElementById('view');
const mode = chooseMode(new URLSearchParams(window.location.search), (q) => window.matchMedia(q),
  softwareGl);
const renderer = makeRenderer(canvas, mode);
const camera = new THREE.PerspectiveCamera(40, 1, 0.05, 20);

const ui = {
  status: document.getElementById('status'),
  lobby: document.getElementById('lobby'),
  players: document.getElementById('players'),
  playersTitle: document.getElementById('players-title'),
  tournaments: document.getElementById('tournaments'),
  tournamentsTitle: document.getElementById('tournaments-title'),
  bracket: document.getElementById('bracket'),
  title: document.getElementById('title'),
  facts: document.getElementById('facts'),
  back: document.getElementById('back'),
  replayControls: document.getElementById('replay-controls'),
  previous: document.getElementById('previous'),
  again: document.getElementById('again'),
  next: document.getElementById('next'),
  scenario: document.getElementById('scenario'),
  replayLast: document.getElementById('replay-last'),
};

const app = {
  socket: null,
  connected: false,
  lobby: [],
  players: [], // the players' records (the gateway's players message)
  player: null, // the player whose page is open: "<server>/<key hex>"
  tournaments: [], // the gateway's tournaments message
  tournament: null, // the tournament whose bracket is open
  match: null, // the match watched
  table: null, // {scene, balls, outer}, once its meshes are in place
  tableName: '',
  builds: 0, // tables asked for: a build finishing after a later one was asked for is dropped
  dressed: false, // whether the table is drawn with the project's meshes
  shadowsOf: '', // the balls the shadow maps were last drawn for
  state: null, // the latest state message
  result: null, // the latest final result
  playback: new PlaybackClock(),
  drawn: [], // the balls as last drawn
  inMotion: false,
  frames: 0,
  replayAsk: null, // the stored shot asked for: {match, shot}
  replay: null, // the stored shot playing (Replay), once the gateway sent it
  replayError: '',
};

const seconds = () => performance.now() / 1000;

function send(object) {
  if (app.socket && app.socket.readyState === WebSocket.OPEN) app.socket.send(JSON.stringify(object));
}

function watch(match) {
  app.replayAsk = null;
  app.replay = null;
  app.match = match;
  app.table = null;
  ++app.builds;
  app.state = null;
  app.result = null;
  app.playback.clear();
  const url = new URL(window.location.href);
  if (match) url.searchParams.set('match', match);
  else url.searchParams.delete('match');
  url.searchParams.delete('shot');
  window.history.replaceState(null, '', url);
  send({ watch: match || '' });
  render();
}

/** Plays stroke `shot` of `match` from the server's store (the page's link says which). */
function askReplay(match, shot) {
  if (app.match) send({ watch: '' });
  app.match = null;
  app.state = null;
  app.result = null;
  app.replay = null;
  app.replayError = '';
  app.replayAsk = { match, shot };
  app.playback.clear();
  window.history.replaceState(null, '', replayLink(match, shot));
  send({ replay: { match, shot } });
  render();
}

/** Opens a tournament's bracket page, or closes it (null). */
function showTournament(id) {
  app.tournament = id;
  const url = new URL(window.location.href);
  if (id) url.searchParams.set('tournament', id);
  else url.searchParams.delete('tournament');
  window.history.replaceState(null, '', url);
  render();
}

/** Opens a player's page ("<server>/<key hex>"), or closes it (null). */
function showPlayer(id) {
  app.player = id;
  const url = new URL(window.location.href);
  if (id) url.searchParams.set('player', id);
  else url.searchParams.delete('player');
  window.history.replaceState(null, '', url);
  render();
}

function connect() {
  const scheme = window.location.protocol === 'https:' ? 'wss' : 'ws';
  const socket = new WebSocket(`${scheme}://${window.location.host}/ws`);
  app.socket = socket;
  socket.onopen = () => {
    app.connected = true;
    ui.status.textContent = 'Connected.';
    const params = new URLSearchParams(window.location.search);
    const wanted = params.get('match');
    const shot = Number.parseInt(params.get('shot') || '', 10);
    if (wanted && wanted !== 'any' && shot >= 1) askReplay(wanted, shot);
    else if (wanted && wanted !== 'any') watch(wanted);
  };
  socket.onclose = () => {
    app.connected = false;
    ui.status.textContent = 'Disconnected from the gateway; trying again…';
    setTimeout(connect, 1000);
  };
  socket.onmessage = (event) => receive(JSON.parse(event.data));
}

function receive(m) {
  switch (m.type) {
    case 'lobby': {
      app.lobby = m.matches;
      const wanted = new URLSearchParams(window.location.search).get('match');
      if (!app.match && wanted === 'any') {
        const first = app.lobby.find((e) => e.in_play);
        if (first) watch(first.match);
      }
      break;
    }
    case 'players':
      app.players = m.players;
      break;
    case 'tournaments':
      app.tournaments = m.tournaments;
      break;
    case 'table': {
      // Drawn once the project's meshes are in (or known missing: the plain table then).
      const build = ++app.builds;
      app.table = null;
      app.tableName = m.name;
      const built = buildTable(m, mode);
      dressTable(built, m, mode).catch((e) => {
        console.warn(`the table's meshes: ${e}`);
        return false;
      }).then((dressed) => {
        if (build !== app.builds) return;
        if (mode.environment) reflect(built, environmentOf(renderer, built.scene, m.ball_radius));
        app.dressed = dressed;
        app.shadowsOf = '';
        app.table = built;
        // A stored shot that came while the table was loading plays from its start now.
        if (app.replay) {
          app.playback.clear();
          app.replay.again(seconds());
        }
        resize();
        render();
      });
      break;
    }
    case 'state':
      if (m.match !== app.match) return;
      app.state = m;
      app.state.state.words = m.verdict_words;
      app.state.state.snooker = m.snooker;
      break;
    case 'result':
      if (m.match !== app.match) return;
      if (m.result.final) app.result = { ...m.result, words: m.verdict_words };
      break;
    case 'frame':
      if (m.match !== app.match) return;
      app.playback.push(m, seconds());
      break;
    case 'replay':
      if (!app.replayAsk || m.match !== app.replayAsk.match || m.shot !== app.replayAsk.shot) return;
      app.playback.clear();
      if (m.found) {
        app.replay = new Replay(m, seconds());
        app.replayError = '';
      } else {
        app.replay = null;
        app.replayError = m.error;
      }
      break;
    case 'gone':
      if (m.match === app.match) ui.status.textContent = 'This match has ended or its server left.';
      break;
    case 'error':
      ui.status.textContent = m.text;
      break;
    default:
      break;
  }
  render();
}

function lobbyEntry(match) {
  return app.lobby.find((e) => e.match === match) || null;
}

/** The lobby list and the HUD, as text. */
function render() {
  ui.lobby.replaceChildren();
  ui.players.replaceChildren();
  ui.tournaments.replaceChildren();
  ui.bracket.replaceChildren();
  ui.bracket.hidden = true;
  ui.tournaments.hidden = ui.tournamentsTitle.hidden = true;
  const replaying = !!app.replayAsk;
  ui.replayControls.hidden = !replaying;
  ui.replayLast.hidden = !(app.match && app.state && app.state.state.shot_number >= 1);
  if (replaying) {
    ui.lobby.hidden = ui.players.hidden = ui.playersTitle.hidden = true;
    ui.back.hidden = false;
    const { match, shot } = app.replayAsk;
    ui.title.textContent = `Replay: shot ${shot} of ${match}`;
    const m = app.replay ? app.replay.message : null;
    const lines = m ? replayLines(m) : [app.replayError || 'Asking the server for the shot…'];
    ui.facts.replaceChildren(...lines.map(line));
    ui.previous.disabled = shot <= 1;
    ui.next.disabled = !m || shot >= m.shots;
    ui.again.disabled = !m;
    ui.scenario.hidden = !m || !m.scenario;
    if (m && m.scenario) {
      ui.scenario.href = `data:application/json;charset=utf-8,${encodeURIComponent(m.scenario)}`;
      ui.scenario.download = `${match}-shot-${shot}.json`;
    }
    return;
  }
  if (!app.match && app.tournament) {
    ui.lobby.hidden = ui.players.hidden = ui.playersTitle.hidden = true;
    ui.back.hidden = false;
    const t = app.tournaments.find((x) => x.tournament === app.tournament);
    ui.title.textContent = t ? t.name : `Tournament ${app.tournament}`;
    ui.facts.replaceChildren(...(t ? [tournamentButtonText(t), ...entrantLines(t)]
      : ['Waiting for the tournament…']).map(line));
    if (!t) return;
    ui.bracket.hidden = false;
    for (const b of bracketLines(t)) {
      const li = document.createElement('li');
      if (b.state === 2) {
        const button = document.createElement('button');
        button.textContent = `Watch ${b.text}`;
        button.onclick = () => watch(b.match);
        li.append(button);
      } else {
        li.textContent = b.text;
      }
      ui.bracket.append(li);
    }
    return;
  }
  const lobbyShown = !app.match && !app.player;
  ui.lobby.hidden = !lobbyShown;
  ui.players.hidden = !lobbyShown;
  ui.playersTitle.hidden = !lobbyShown || !app.players.length;
  ui.back.hidden = lobbyShown;
  if (!app.match && app.player) {
    const records = byPlayer(app.players).get(app.player) || [];
    ui.title.textContent = records.length ? `Player ${records[0].name}` : 'Player';
    const lines = records.flatMap(playerLines);
    ui.facts.replaceChildren(...(lines.length ? lines : ['No statistics yet.']).map(line));
    return;
  }
  if (!app.match) {
    ui.title.textContent = 'Matches on this network';
    if (!app.lobby.length) {
      const li = document.createElement('li');
      li.textContent = app.connected ? 'No match is open yet.' : 'Connecting…';
      ui.lobby.append(li);
    }
    for (const entry of app.lobby) {
      const li = document.createElement('li');
      const button = document.createElement('button');
      button.textContent = `Watch ${describeEntry(entry)}`;
      button.onclick = () => watch(entry.match);
      li.append(button);
      ui.lobby.append(li);
    }
    ui.tournaments.hidden = ui.tournamentsTitle.hidden = !app.tournaments.length;
    for (const t of app.tournaments) {
      const li = document.createElement('li');
      const button = document.createElement('button');
      button.textContent = tournamentButtonText(t);
      button.onclick = () => showTournament(t.tournament);
      li.append(button);
      ui.tournaments.append(li);
    }
    for (const [id, records] of byPlayer(app.players)) {
      const li = document.createElement('li');
      const button = document.createElement('button');
      button.textContent = playerButtonText(records);
      button.onclick = () => showPlayer(id);
      li.append(button);
      ui.players.append(li);
    }
    ui.facts.replaceChildren();
    return;
  }
  if (!app.state) {
    ui.title.textContent = `Match ${app.match}`;
    ui.facts.replaceChildren(line('Waiting for the match…'));
    return;
  }
  const facts = describe(app.state.state, app.state.settings, app.result, lobbyEntry(app.match));
  ui.title.textContent = facts.title;
  ui.facts.replaceChildren(...[facts.players, facts.score, facts.breaks, facts.turn, facts.groups,
    facts.last].filter((t) => t).map(line));
}

function line(text) {
  const p = document.createElement('p');
  p.textContent = text;
  return p;
}

function resize() {
  const width = canvas.clientWidth;
  const height = canvas.clientHeight;
  if (!width || !height) return;
  renderer.setSize(width, height, false);
  if (app.table) {
    // The shades hang in view over the far rail of a landscape view of the hall; a view that
    // looks down past them onto the table (portrait, or the light mode's) leaves them out.
    const clear = fitCamera(camera, app.table.outer, width / height, mode.hall);
    app.table.shades.visible = clear && shadesShown;
  }
}
window.addEventListener('resize', resize);
let shadesShown = true;

/** Draws the table with `balls` placed; the shadow maps only when the balls moved. */
function draw(balls) {
  placeBalls(app.table.balls, balls);
  app.drawn = balls;
  const key = balls.map((b) => b.join(',')).join(';');
  if (key !== app.shadowsOf) {
    renderer.shadowMap.needsUpdate = true;
    app.shadowsOf = key;
  }
  renderer.render(app.table.scene, camera);
  ++app.frames;
}
renderer.shadowMap.autoUpdate = false;

function frame() {
  requestAnimationFrame(frame);
  if (!app.table) {
    renderer.setClearColor(0x151210);
    renderer.clear();
    return;
  }
  if (app.replay) {
    const now = seconds();
    for (const f of app.replay.due(now)) app.playback.push(f, now);
    const played = app.playback.sample(now);
    app.inMotion = app.replay.next > 0 && !(app.replay.handedOut() && app.playback.caughtUp());
    draw(app.inMotion && played ? played : app.replay.still());
    return;
  }
  const settled = app.state ? app.state.state.shot_number : 0;
  const played = app.playback.sample(seconds());
  app.inMotion = app.playback.inMotion(settled);
  // Frames while the shot plays; the state's layout at rest once the playback has caught up
  // with a state that counts the shot.
  draw(app.inMotion && played ? played : app.state ? app.state.balls : played || []);
}

// Back to the lobby, from a match, a replay or a player's page alike.
ui.back.onclick = () => {
  app.player = null;
  if (app.match || app.replayAsk) watch(null);
  else if (app.tournament) showTournament(null);
  else showPlayer(null);
};
ui.previous.onclick = () => app.replayAsk && askReplay(app.replayAsk.match, app.replayAsk.shot - 1);
ui.next.onclick = () => app.replayAsk && askReplay(app.replayAsk.match, app.replayAsk.shot + 1);
ui.again.onclick = () => {
  if (!app.replay) return;
  app.playback.clear();
  app.replay.again(seconds());
};
ui.replayLast.onclick = () => {
  if (app.match && app.state) askReplay(app.match, app.state.state.shot_number);
};
app.player = new URLSearchParams(window.location.search).get('player');
app.tournament = new URLSearchParams(window.location.search).get('tournament');
resize();
connect();
render();
requestAnimationFrame(frame);

/** For tests: the page's own projection and what it shows. */
window.poolTest = {
  /** Pixel position (CSS px from the page's top left) of a table-frame point, metres. */
  project(x, y, z) {
    const v = new THREE.Vector3(x, y, z).project(camera);
    const r = canvas.getBoundingClientRect();
    return [r.left + ((v.x + 1) / 2) * r.width, r.top + ((1 - v.y) / 2) * r.height];
  },
  /** The camera as drawn: its view (world to camera) and projection matrices, column-major, and
   * the canvas's rectangle (CSS px), for a test to project with its own arithmetic. */
  camera() {
    camera.updateMatrixWorld();
    const r = canvas.getBoundingClientRect();
    return {
      view: camera.matrixWorldInverse.elements.slice(),
      projection: camera.projectionMatrix.elements.slice(),
      rect: [r.left, r.top, r.width, r.height],
    };
  },
  /** Shows or hides the lamps' shades (for a test to see what they cover). */
  showShades(on) {
    shadesShown = on;
    resize();
  },
  /** Takes one message as if the gateway had sent it (a table or a state drawn without a match
   * on the wire). */
  receive(message) {
    receive(message);
  },
  status() {
    return {
      connected: app.connected,
      match: app.match,
      table: app.tableName,
      mode: mode.name,
      ready: !!app.table,
      dressed: app.dressed,
      revision: app.state ? app.state.state.revision : null,
      shotNumber: app.state ? app.state.state.shot_number : null,
      phase: app.state ? app.state.state.phase : null,
      inMotion: app.inMotion,
      frames: app.frames,
      drawn: app.drawn.map((b) => ({ id: b[0], x: b[1], y: b[2], z: b[3], on: b[8] === 1 })),
      replay: app.replayAsk ? {
        match: app.replayAsk.match,
        shot: app.replayAsk.shot,
        found: app.replay ? true : app.replayError ? false : null,
        shots: app.replay ? app.replay.message.shots : null,
        error: app.replayError,
        started: app.replay ? app.replay.next > 0 : false,
        done: app.replay ? app.replay.handedOut() && !app.inMotion : false,
        lines: app.replay ? replayLines(app.replay.message) : [],
      } : null,
      tournaments: app.tournaments.map((t) => ({
        id: t.tournament,
        text: tournamentButtonText(t),
        entrants: entrantLines(t),
        bracket: bracketLines(t).map((b) => b.text),
      })),
      lobby: app.lobby.length,
      lobbyLines: app.lobby.map((e) => ({ match: e.match, text: describeEntry(e) })),
      players: [...byPlayer(app.players)].map(([id, records]) => ({
        id,
        text: playerButtonText(records),
        lines: records.flatMap(playerLines),
      })),
    };
  },
};
