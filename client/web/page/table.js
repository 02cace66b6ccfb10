// The table and balls in three.js, from the gateway's table message: felt (a snooker table's with
// its baulk line, D and spots chalked on it), cushions along the nose lines, wooden rails, pocket
// holes (the plain table, until hall.js puts the project's meshes in its place), the two lamps'
// spot lights casting the balls' shadows, and numbered balls, clear-coated in the full mode, in
// the game window's colours (linear RGB, as its palette gives them).
import * as THREE from './three.module.js';

const RAIL_HEIGHT_OVER_NOSE = 1.15;

function linear(rgb) {
  return new THREE.Color().setRGB(rgb[0], rgb[1], rgb[2], THREE.LinearSRGBColorSpace);
}

/** A ball's texture: its colour (a band around the body's z for stripes), a white circle with
 * its number (if it has one: a carom set has none) on the body's +x and -x sides, as the game's
 * ball shader draws it. */
function ballTexture(id, look) {
  const canvas = document.createElement('canvas');
  canvas.width = 256;
  canvas.height = 128;
  const g = canvas.getContext('2d');
  const colour = linear(look.colour).getStyle();
  if (id === 0) {
    g.fillStyle = linear([0.95, 0.95, 0.92]).getStyle();
    g.fillRect(0, 0, 256, 128);
  } else if (look.striped) {
    g.fillStyle = linear([0.95, 0.95, 0.92]).getStyle();
    g.fillRect(0, 0, 256, 128);
    g.fillStyle = colour;
    g.fillRect(0, 128 / 3, 256, 128 / 3);
  } else {
    g.fillStyle = colour;
    g.fillRect(0, 0, 256, 128);
  }
  if (look.number > 0) {
    for (const cx of [0, 128, 256]) {
      g.fillStyle = '#f2f2ea';
      g.beginPath();
      g.arc(cx, 64, 17, 0, 2 * Math.PI);
      g.fill();
      g.fillStyle = '#101010';
      g.font = 'bold 20px sans-serif';
      g.textAlign = 'center';
      g.textBaseline = 'middle';
      g.fillText(String(look.number), cx, 65);
    }
  }
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  texture.anisotropy = 4;
  return texture;
}

/** The cloth of a snooker table's bed (`sx` × `sy` m, centred on the table) as a texture: the
 * felt with the baulk line, the D and the six spots chalked on it, as the window's marked felt
 * mixes chalk into the felt (`marks.strength` of it where a mark covers); null for a table
 * without marks. About 1.8 mm a texel, mipmapped: a line thinner than a pixel shows fainter,
 * never broken. */
function markedCloth(table, sx, sy) {
  const marks = table.snooker_marks;
  if (!marks) return null;
  const perMetre = 560;
  const canvas = document.createElement('canvas');
  canvas.width = Math.ceil(sx * perMetre);
  canvas.height = Math.ceil(sy * perMetre);
  const g = canvas.getContext('2d');
  const felt = table.colours.felt;
  const s = marks.strength;
  const chalk = table.colours.chalk.map((v, i) => felt[i] * (1 - s) + v * s);
  g.fillStyle = linear(felt).getStyle();
  g.fillRect(0, 0, canvas.width, canvas.height);
  // The table frame: x to the right, y up the canvas, metres.
  g.setTransform(canvas.width / sx, 0, 0, -canvas.height / sy, canvas.width / 2, canvas.height / 2);
  g.strokeStyle = g.fillStyle = linear(chalk).getStyle();
  g.lineWidth = marks.line_width;
  const halfWidth = table.width / 2;
  const brown = marks.spots.brown;
  g.beginPath();
  g.moveTo(marks.baulk_x, -halfWidth);
  g.lineTo(marks.baulk_x, halfWidth);
  g.stroke();
  g.beginPath(); // the D: from +y round through -x (the baulk side) to -y
  g.arc(brown[0], brown[1], marks.d_radius, Math.PI / 2, 1.5 * Math.PI);
  g.stroke();
  for (const at of Object.values(marks.spots)) {
    g.beginPath();
    g.arc(at[0], at[1], marks.spot_radius, 0, 2 * Math.PI);
    g.fill();
  }
  const texture = new THREE.CanvasTexture(canvas);
  texture.colorSpace = THREE.SRGBColorSpace;
  texture.anisotropy = 8;
  return texture;
}

/** The hall's ambient light, a share of the albedo: a white ball in a corner, out of both
 * lamps' cones, still reads as white, and the felt under a lamp stays at least 1.5 times as
 * bright as midway between the lamps. */
export const AMBIENT = 0.18;

/** The ball's material: clear-coated over a glossy base reflecting `environment` (full mode), or
 * plain Phong gloss (light mode). */
function ballMaterial(map, mode) {
  if (mode.clearcoat) {
    return new THREE.MeshPhysicalMaterial({ map, roughness: 0.3, clearcoat: 1.0,
      clearcoatRoughness: 0.12, envMapIntensity: 1.0 });
  }
  return new THREE.MeshPhongMaterial({ map, shininess: 150,
    specular: new THREE.Color().setRGB(0.35, 0.35, 0.35, THREE.LinearSRGBColorSpace) });
}

/** Builds the scene of one table in `mode` (look.js); returns {scene, balls: Map(id → mesh),
 * outer: [x, y], railTop, materials (the table's, by look), plain (the plain table's group)}. */
export function buildTable(table, mode) {
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0x151210);
  const c = table.colours;
  const cw = table.cushion_width;
  const rw = table.rail_width;
  const railTop = table.nose_height * RAIL_HEIGHT_OVER_NOSE;
  const outer = [table.length / 2 + cw + rw, table.width / 2 + cw + rw];

  // The game's light: an ambient share of the albedo and each lamp's spot cone with its gain over
  // a felt straight below it, falling off with the square of the distance (the cones of the
  // game's high preset: the felt midway between the lamps gets a quarter of a lamp's light from
  // each). three's Lambert term
  // divides by π: the intensities below make a point straight under a lamp get `gain` of its
  // albedo, as in the game's shader. In full mode each lamp casts soft shadows (three's shadow
  // map, from the light itself, its cone the shadow camera's).
  scene.add(new THREE.AmbientLight(0xffffff, AMBIENT * Math.PI));
  const lamps = table.lamps;
  const cone = lamps.high || lamps; // the game's high preset's cones, where the message has them
  for (const p of lamps.positions) {
    const spot = new THREE.SpotLight(0xffffff, lamps.gain * Math.PI * p[2] * p[2]);
    spot.position.set(p[0], p[1], p[2]);
    spot.target.position.set(p[0], p[1], 0);
    spot.angle = THREE.MathUtils.degToRad(cone.outer_deg);
    spot.penumbra = 1 - cone.inner_deg / cone.outer_deg;
    spot.decay = 2;
    if (mode.shadows) {
      spot.castShadow = true;
      spot.shadow.mapSize.set(mode.shadowSize, mode.shadowSize);
      spot.shadow.camera.near = 0.3;
      spot.shadow.camera.far = 2.5;
      spot.shadow.radius = 4;
      spot.shadow.bias = -0.0004;
      spot.shadow.normalBias = 0.002;
    }
    scene.add(spot, spot.target);
  }

  const felt = new THREE.MeshLambertMaterial({ color: linear(c.felt) });
  const cloth = markedCloth(table, table.length + 2 * cw, table.width + 2 * cw);
  const bedMaterial = cloth ? new THREE.MeshLambertMaterial({ map: cloth }) : felt;
  const cushion = new THREE.MeshLambertMaterial({ color: linear(c.cushion) });
  // Lacquered wood reflecting the hall in full mode; matt in light mode (the cheaper shader).
  const wood = mode.environment
    ? new THREE.MeshStandardMaterial({ color: linear(c.wood), roughness: 0.45, metalness: 0.0 })
    : new THREE.MeshLambertMaterial({ color: linear(c.wood) });
  const pocket = new THREE.MeshBasicMaterial({ color: linear(c.pocket) });
  const dark = new THREE.MeshLambertMaterial({ color: linear(c.pocket) });
  const materials = { bed: bedMaterial, cushion, wood, dark };

  const plain = new THREE.Group();
  scene.add(plain);
  const bed = new THREE.Mesh(new THREE.PlaneGeometry(table.length + 2 * cw, table.width + 2 * cw),
    bedMaterial);
  bed.receiveShadow = true;
  plain.add(bed);

  // Cushions: each nose segment pushed back by the cushion's width, up to the rail's top.
  for (const nose of table.noses) {
    const [ax, ay] = nose.a;
    const [bx, by] = nose.b;
    const [nx, ny] = nose.normal;
    const shape = new THREE.Shape([
      new THREE.Vector2(ax, ay), new THREE.Vector2(bx, by),
      new THREE.Vector2(bx - nx * cw, by - ny * cw), new THREE.Vector2(ax - nx * cw, ay - ny * cw),
    ]);
    const geometry = new THREE.ExtrudeGeometry(shape, { depth: railTop * 0.97, bevelEnabled: false });
    plain.add(new THREE.Mesh(geometry, cushion));
  }

  // Rails: a wooden frame round the cushions.
  const railBox = (sx, sy, x, y) => {
    const m = new THREE.Mesh(new THREE.BoxGeometry(sx, sy, railTop), wood);
    m.position.set(x, y, railTop / 2);
    plain.add(m);
  };
  const ix = table.length / 2 + cw;
  const iy = table.width / 2 + cw;
  railBox(2 * outer[0], rw, 0, iy + rw / 2);
  railBox(2 * outer[0], rw, 0, -iy - rw / 2);
  railBox(rw, 2 * iy, ix + rw / 2, 0);
  railBox(rw, 2 * iy, -ix - rw / 2, 0);

  // Pockets: the holes, dark, on the bed and over the rails round them.
  for (const hole of table.holes) {
    for (const z of [0.0005, railTop + 0.0005]) {
      const disc = new THREE.Mesh(new THREE.CircleGeometry(hole.radius, 32), pocket);
      disc.position.set(hole.centre[0], hole.centre[1], z);
      plain.add(disc);
    }
  }

  const balls = new Map();
  const sphere = new THREE.SphereGeometry(table.ball_radius, mode.sphere[0], mode.sphere[1]);
  sphere.rotateX(Math.PI / 2); // the texture's poles on the body's z, as the game's balls
  c.balls.forEach((look, id) => {
    const mesh = new THREE.Mesh(sphere, ballMaterial(ballTexture(id, look), mode));
    mesh.visible = false;
    mesh.castShadow = true;
    balls.set(id, mesh);
    scene.add(mesh);
  });
  const shades = new THREE.Group(); // the lamps' shades, once hall.js has them
  scene.add(shades);
  return { scene, balls, outer, railTop, materials, plain, shades };
}

/** Gives the balls and the wood `environment` (a prefiltered map of the hall) to reflect. */
export function reflect(built, environment) {
  for (const mesh of built.balls.values()) {
    mesh.material.envMap = environment;
    mesh.material.needsUpdate = true;
  }
  built.materials.wood.envMap = environment;
  built.materials.wood.envMapIntensity = 0.5;
  built.materials.wood.needsUpdate = true;
  if (built.materials.shade) {
    built.materials.shade.envMap = environment;
    built.materials.shade.needsUpdate = true;
  }
}

/** Places the balls: [id, x, y, z, qw, qx, qy, qz, onTable] each; balls off the table hidden. */
export function placeBalls(balls, list) {
  const seen = new Set();
  for (const b of list) {
    const mesh = balls.get(b[0]);
    if (!mesh) continue;
    seen.add(b[0]);
    mesh.visible = b[8] === 1;
    mesh.position.set(b[1], b[2], b[3]);
    mesh.quaternion.set(b[5], b[6], b[7], b[4]);
  }
  for (const [id, mesh] of balls) if (!seen.has(id)) mesh.visible = false;
}

/** A camera looking down on the table from its near side, the table's length across the wider
 * side of the view; fitted so the whole table shows. Tilted 18° from straight down, looking down
 * past the lamps; 40° in a landscape view of the hall (`hall`), so that the lamps hang over the
 * far rail with the hall behind them. Returns whether the lamps' shades are clear of the table. */
export function fitCamera(camera, outer, aspect, hall = false) {
  const wide = hall && aspect >= 1;
  const tilt = THREE.MathUtils.degToRad(wide ? 40 : 18);
  const half = Math.tan(THREE.MathUtils.degToRad(camera.fov / 2));
  const portrait = aspect < 1;
  const across = portrait ? outer[1] : outer[0];
  const along = portrait ? outer[0] : outer[1];
  // A tilted view brings the near corners closer: more room round them.
  const distance = (wide ? 1.2 : 1.08) * Math.max(along / half, across / (half * aspect)) + 0.1;
  camera.aspect = aspect;
  camera.up.set(0, 0, 1);
  if (portrait) camera.position.set(-distance * Math.sin(tilt), 0, distance * Math.cos(tilt));
  else camera.position.set(0, -distance * Math.sin(tilt), distance * Math.cos(tilt));
  camera.lookAt(0, 0, 0);
  if (portrait) {
    // Long side up the screen: roll the view so the table's +x points up.
    camera.up.set(1, 0, 0);
    camera.lookAt(0, 0, 0);
  }
  camera.near = 0.05;
  camera.far = 20;
  camera.updateProjectionMatrix();
  return wide;
}
