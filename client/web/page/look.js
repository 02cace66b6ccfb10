// How the page draws: in full (three's soft shadow maps from both lamps, the hall's meshes round
// the table, the lamps' shades, clear-coated balls reflecting the hall) or light, for phones (no
// shadow maps, the table's meshes alone, glossy balls without reflections, one device pixel a
// pixel), with ACES filmic tone mapping to sRGB either way. ?light or ?full in the URL chooses;
// else a narrow or touch screen, or a browser drawing without a GPU (software GL), gets the light
// mode.
import * as THREE from './three.module.js';

/** The two modes' settings. */
export const MODES = {
  full: { name: 'full', shadows: true, shadowSize: 1024, hall: true, clearcoat: true,
    environment: true, maxPixelRatio: 2, sphere: [32, 16] },
  light: { name: 'light', shadows: false, shadowSize: 0, hall: false, clearcoat: false,
    environment: false, maxPixelRatio: 1, sphere: [20, 12] },
};

/** The exposure the tone mapping starts from: a white ball lit by the ambient light alone still
 * reads as white, and the felt under a lamp at least 1.5 times as bright as midway between
 * them (see docs/WEB.md). */
export const EXPOSURE = 1.2;

/** Whether the browser's WebGL draws without a GPU (SwiftShader, llvmpipe: a few frames a
 * second in full mode). */
export function softwareGl() {
  const gl = document.createElement('canvas').getContext('webgl2');
  if (!gl) return true;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = info ? String(gl.getParameter(info.UNMASKED_RENDERER_WEBGL)) : '';
  const lose = gl.getExtension('WEBGL_lose_context');
  if (lose) lose.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

/** The mode `params` (the URL's search parameters) ask for, else the one that suits the screen
 * `media` (window.matchMedia) describes and the GL (`software`: softwareGl's answer, asked only
 * then); `antialias=0` and `shadows=0` turn those off (for tests that must see the difference). */
export function chooseMode(params, media, software) {
  let mode = MODES.full;
  if (params.has('light')) mode = MODES.light;
  else if (params.has('full')) mode = MODES.full;
  else if (media('(max-width: 40rem), (max-height: 30rem), (pointer: coarse)').matches) {
    mode = MODES.light;
  } else if (software()) {
    mode = MODES.light;
  }
  const antialias = params.get('antialias') !== '0';
  const shadows = mode.shadows && params.get('shadows') !== '0';
  return { ...mode, antialias, shadows };
}

/** The page's renderer for `mode` on `canvas`. */
export function makeRenderer(canvas, mode) {
  const renderer = new THREE.WebGLRenderer({
    canvas,
    antialias: mode.antialias,
    preserveDrawingBuffer: true,
    powerPreference: mode.name === 'light' ? 'low-power' : 'high-performance',
  });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, mode.maxPixelRatio));
  renderer.toneMapping = THREE.ACESFilmicToneMapping;
  renderer.toneMappingExposure = EXPOSURE;
  renderer.outputColorSpace = THREE.SRGBColorSpace;
  renderer.shadowMap.enabled = mode.shadows;
  // PCF with a filter radius: three's soft shadows (its PCFSoftShadowMap now maps to this).
  renderer.shadowMap.type = THREE.PCFShadowMap;
  return renderer;
}

/** The environment the balls reflect: `scene` (the hall, the table and the lamps' shades, its
 * balls not yet shown) seen from just above the middle of the bed, prefiltered by three's
 * PMREMGenerator. */
export function environmentOf(renderer, scene, ballRadius) {
  const pmrem = new THREE.PMREMGenerator(renderer);
  const target = pmrem.fromScene(scene, 0.02, 0.02, 30, {
    size: 128,
    position: new THREE.Vector3(0, 0, 2 * ballRadius),
  });
  pmrem.dispose();
  return target.texture;
}
