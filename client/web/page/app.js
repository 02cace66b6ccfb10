// The web spectator: connects to the gateway's WebSocket, shows the lobby, follows the chosen
// match (late join: the table, the latest state and result at once) and draws it with three.js.
import * as THREE from './three.module.js';
import { PlaybackClock } from './playback.js';
import { buildTable, placeBalls, fitCamera } from './table.js';
import { describe, describeEntry } from './hud.js';
import { byPlayer, playerButtonText, playerLines } from './players.js';

const canvas = document.getElementById('view');
const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
const camera = new THREE.PerspectiveCamera(40, 1, 0.05, 20);

const ui = {
  status: document.getElementById('status'),
  lobby: document.getElementById('lobby'),
  players: document.getElementById('players'),
  playersTitle: document.getElementById('players-title'),
  title: document.getElementById('title'),
  facts: document.getElementById('facts'),
  back: document.getElementById('back'),
};

const app = {
  socket: null,
  connected: false,
  lobby: [],
  players: [], // the players' records (the gateway's players message)
  player: null, // the player whose page is open: "<server>/<key hex>"
  match: null, // the match watched
  table: null, // {scene, balls, outer}
  tableName: '',
  state: null, // the latest state message
  result: null, // the latest final result
  playback: new PlaybackClock(),
  drawn: [], // the balls as last drawn
  inMotion: false,
  frames: 0,
};

const seconds = () => performance.now() / 1000;

function send(object) {
  if (app.socket && app.socket.readyState === WebSocket.OPEN) app.socket.send(JSON.stringify(object));
}

function watch(match) {
  app.match = match;
  app.table = null;
  app.state = null;
  app.result = null;
  app.playback.clear();
  const url = new URL(window.location.href);
  if (match) url.searchParams.set('match', match);
  else url.searchParams.delete('match');
  window.history.replaceState(null, '', url);
  send({ watch: match || '' });
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
    const wanted = new URLSearchParams(window.location.search).get('match');
    if (wanted && wanted !== 'any') watch(wanted);
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
    case 'table':
      app.table = buildTable(m);
      app.tableName = m.name;
      resize();
      break;
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
  if (app.table) fitCamera(camera, app.table.outer, width / height);
}
window.addEventListener('resize', resize);

function frame() {
  requestAnimationFrame(frame);
  if (!app.table) {
    renderer.setClearColor(0x151210);
    renderer.clear();
    return;
  }
  const settled = app.state ? app.state.state.shot_number : 0;
  const played = app.playback.sample(seconds());
  app.inMotion = app.playback.inMotion(settled);
  // Frames while the shot plays; the state's layout at rest once the playback has caught up
  // with a state that counts the shot.
  const balls = app.inMotion && played ? played : app.state ? app.state.balls : played || [];
  placeBalls(app.table.balls, balls);
  app.drawn = balls;
  renderer.render(app.table.scene, camera);
  ++app.frames;
}

// Back to the lobby, from a match or a player's page alike.
ui.back.onclick = () => {
  app.player = null;
  if (app.match) watch(null);
  else showPlayer(null);
};
app.player = new URLSearchParams(window.location.search).get('player');
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
      revision: app.state ? app.state.state.revision : null,
      shotNumber: app.state ? app.state.state.shot_number : null,
      phase: app.state ? app.state.state.phase : null,
      inMotion: app.inMotion,
      frames: app.frames,
      drawn: app.drawn.map((b) => ({ id: b[0], x: b[1], y: b[2], z: b[3], on: b[8] === 1 })),
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
