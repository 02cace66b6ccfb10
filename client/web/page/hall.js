// The project's meshes in the page, loaded with three's OBJLoader from pool-web's /assets/: the
// table's own (slate, cushions, jaws, rails), its dressing (rail tops, apron, legs, the pockets'
// leather), the diamonds on the rails, the hall round it and the lamps' shades over it, coloured
// as the game's palette gives them (the table message's colours and looks). Parts of one look
// are merged into one mesh: a draw call each.
import * as THREE from './three.module.js';

let addons = null;

/** Three's OBJLoader and mergeGeometries, imported once (pool-web serves them beside three). */
function loadAddons() {
  if (!addons) {
    addons = Promise.all([import('./OBJLoader.js'), import('./BufferGeometryUtils.js')])
      .then(([obj, utils]) => ({ OBJLoader: obj.OBJLoader, merge: utils.mergeGeometries }));
  }
  return addons;
}

function linear(rgb, scale = 1) {
  return new THREE.Color().setRGB(rgb[0] * scale, rgb[1] * scale, rgb[2] * scale,
    THREE.LinearSRGBColorSpace);
}

/** The OBJ at `url` merged by look: [[key, geometry]] for the parts `keyOf(name)` names (null
 * leaves a part out). */
async function mergedParts(url, keyOf) {
  const { OBJLoader, merge } = await loadAddons();
  const group = await new OBJLoader().loadAsync(url);
  const byKey = new Map();
  group.traverse((o) => {
    if (!o.isMesh) return;
    const key = keyOf(o.name);
    if (!key) return;
    const g = o.geometry;
    for (const name of Object.keys(g.attributes)) {
      if (name !== 'position' && name !== 'normal') g.deleteAttribute(name);
    }
    g.clearGroups();
    if (!byKey.has(key)) byKey.set(key, []);
    byKey.get(key).push(g);
  });
  return [...byKey].map(([key, list]) => [key, list.length === 1 ? list[0] : merge(list)]);
}

/** Planar texture coordinates over the bed (`sx` × `sy` m, centred), for the marked cloth. */
function bedUv(geometry, sx, sy) {
  const p = geometry.attributes.position;
  const uv = new Float32Array(p.count * 2);
  for (let i = 0; i < p.count; ++i) {
    uv[2 * i] = p.getX(i) / sx + 0.5;
    uv[2 * i + 1] = p.getY(i) / sy + 0.5;
  }
  geometry.setAttribute('uv', new THREE.BufferAttribute(uv, 2));
}

/** The table part `name`'s look as the game's palette names it: felt, cushion, wood or dark;
 * null for the parts the dressing draws over (the rails, the pockets' cylinders, the trough). */
function tablePartKey(name, dressed) {
  if (name === 'slate') return 'felt';
  if (name.startsWith('cushion_') || name.startsWith('jaw_')) return 'cushion';
  const over = name.startsWith('rail_') || name.startsWith('pocket_') || name === 'trough';
  if (over && dressed) return null;
  if (name.startsWith('rail_') || name === 'trough') return 'wood';
  return 'dark';
}

/** The hall's parts a light mode leaves out: all but the table's dressing seen from above. */
const UNSEEN_FROM_ABOVE = new Set(['apron', 'underside', 'leg']);

/**
 * Replaces the plain table in `built` (buildTable's) with the project's meshes: the table's and
 * its dressing always (in light mode only the dressing's parts seen from above), the hall and the
 * lamps' shades and cords in full mode. Resolves to whether the meshes were found (the plain
 * table stays otherwise).
 */
export async function dressTable(built, table, mode) {
  const meshes = table.meshes;
  if (!meshes || !meshes.table) return false;
  const { scene, materials, plain } = built;
  const looks = table.looks || {};
  const dressed = !!meshes.dressing;
  const cw = table.cushion_width;
  const [tableParts, dressingParts, roomParts, shadeParts] = await Promise.all([
    mergedParts(meshes.table, (name) => tablePartKey(name, dressed)),
    dressed ? mergedParts(meshes.dressing,
      (name) => (!mode.hall && UNSEEN_FROM_ABOVE.has(name) ? null : name)) : [],
    mode.hall && meshes.room ? mergedParts(meshes.room, (name) => name) : [],
    mode.hall && meshes.shade ? mergedParts(meshes.shade, (name) => name) : [],
  ]);
  const group = new THREE.Group();
  const add = (geometry, material, shadows) => {
    const mesh = new THREE.Mesh(geometry, material);
    mesh.receiveShadow = shadows.receive;
    mesh.castShadow = shadows.cast;
    group.add(mesh);
    return mesh;
  };
  for (const [key, geometry] of tableParts) {
    if (key === 'felt' && materials.bed.map) bedUv(geometry, table.length + 2 * cw, table.width + 2 * cw);
    const material = key === 'felt' ? materials.bed : materials[key];
    // The balls' shadows fall on the bed and the cushions (the shadow maps' only lookups).
    const felt = key === 'felt' || key === 'cushion';
    add(geometry, material, { receive: felt, cast: key === 'cushion' });
  }
  const lookMaterial = (name) => {
    const colour = linear(looks[name] || [0.5, 0.5, 0.5]);
    if (name === 'rail_top' || name === 'rail_edge' || name === 'apron' || name === 'leg') {
      return materials.wood;
    }
    // The pockets' leather is seen from inside: both faces drawn.
    const side = name.startsWith('pocket_') ? THREE.DoubleSide : THREE.FrontSide;
    return new THREE.MeshLambertMaterial({ color: colour, side });
  };
  for (const [name, geometry] of dressingParts) {
    add(geometry, lookMaterial(name), { receive: false, cast: false });
  }
  for (const [name, geometry] of roomParts) {
    // After the table: what it hides of the floor is never shaded.
    add(geometry, lookMaterial(name), { receive: false, cast: false }).renderOrder = 1;
  }
  // The lamps' shades, enamel round each light, and their cords up to the ceiling (shown where
  // the view has them over the far rail: app.js).
  const shade = new THREE.MeshStandardMaterial({
    color: linear(table.lamps.shade), roughness: 0.35, metalness: 0.0, side: THREE.DoubleSide,
  });
  const cord = new THREE.MeshLambertMaterial({ color: linear(table.lamps.shade, 0.3) });
  for (const [name, geometry] of shadeParts) {
    for (const p of table.lamps.positions) {
      const mesh = new THREE.Mesh(geometry, name === 'cord' ? cord : shade);
      mesh.position.set(p[0], p[1], p[2]);
      built.shades.add(mesh);
    }
  }
  materials.shade = shade;
  // The diamonds: one inlay, instanced along the rails, a quarter turn on the end rails.
  if (table.diamonds && table.diamonds.length && table.diamond_size) {
    const [hl, hs] = table.diamond_size;
    const rhombus = new THREE.Shape([new THREE.Vector2(hl, 0), new THREE.Vector2(0, hs),
      new THREE.Vector2(-hl, 0), new THREE.Vector2(0, -hs)]);
    const inlay = new THREE.InstancedMesh(new THREE.ShapeGeometry(rhombus),
      new THREE.MeshLambertMaterial({ color: linear(looks.bead_light || [0.9, 0.9, 0.8]) }),
      table.diamonds.length);
    const m = new THREE.Matrix4();
    const turn = new THREE.Quaternion();
    const long = table.diamonds.length - 6; // the end rails' six come last
    table.diamonds.forEach((d, i) => {
      turn.setFromAxisAngle(new THREE.Vector3(0, 0, 1), i >= long ? Math.PI / 2 : 0);
      m.compose(new THREE.Vector3(d[0], d[1], d[2] + 0.0008), turn, new THREE.Vector3(1, 1, 1));
      inlay.setMatrixAt(i, m);
    });
    group.add(inlay);
  }
  scene.remove(plain);
  scene.add(group);
  return true;
}
