// What a page costs in headless Chromium, measured from outside its code: a script run before
// the page's own counts each WebGL draw call and its triangles per animation frame, times each
// frame's callback with the GPU's work finished (gl.finish), and the intervals between frames;
// the page's downloads come from its resource timing entries.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace pool::client::test {

/// Installed with Page.addScriptToEvaluateOnNewDocument: wraps WebGL's draw calls and
/// requestAnimationFrame; window.poolMeter.reset() starts a sample, window.poolMeter.read()
/// returns {frames, interval_ms, work_ms, calls, triangles} (medians over the sample's frames
/// that drew anything) and bytes (the encoded bodies of every resource and the document).
inline const char* pageMeterScript() {
  return R"JS((() => {
  let calls = 0, triangles = 0, gl = null;
  const sample = { intervals: [], work: [], calls: [], triangles: [] };
  let last = 0;
  const wrap = (proto) => {
    if (!proto) return;
    for (const name of ['drawArrays', 'drawElements', 'drawArraysInstanced',
      'drawElementsInstanced']) {
      const f = proto[name];
      if (!f) continue;
      const arrays = name.startsWith('drawArrays');
      const instanced = name.endsWith('Instanced');
      proto[name] = function (...a) {
        gl = this;
        const count = arrays ? a[2] : a[1];
        const times = instanced ? (arrays ? a[3] : a[4]) : 1;
        ++calls;
        if (a[0] === this.TRIANGLES) triangles += (count / 3) * times;
        return f.apply(this, a);
      };
    }
  };
  wrap(window.WebGLRenderingContext && WebGLRenderingContext.prototype);
  wrap(window.WebGL2RenderingContext && WebGL2RenderingContext.prototype);
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (callback) => raf((t) => {
    calls = 0;
    triangles = 0;
    const t0 = performance.now();
    callback(t);
    if (gl) gl.finish();
    const t1 = performance.now();
    if (calls > 0) {
      if (last > 0) sample.intervals.push(t0 - last);
      sample.work.push(t1 - t0);
      sample.calls.push(calls);
      sample.triangles.push(triangles);
    }
    last = t0;
  });
  const median = (v) => {
    if (!v.length) return null;
    const s = [...v].sort((a, b) => a - b);
    return s[Math.floor(s.length / 2)];
  };
  window.poolMeter = {
    reset() {
      for (const k of Object.keys(sample)) sample[k] = [];
      last = 0;
    },
    read() {
      let bytes = 0;
      for (const e of performance.getEntriesByType('navigation')) bytes += e.encodedBodySize;
      for (const e of performance.getEntriesByType('resource')) bytes += e.encodedBodySize;
      const mean = sample.intervals.length
        ? sample.intervals.reduce((a, b) => a + b, 0) / sample.intervals.length : null;
      return {
        frames: sample.work.length,
        interval_ms: mean,
        work_ms: median(sample.work),
        calls: median(sample.calls),
        triangles: median(sample.triangles),
        bytes,
      };
    },
  };
})();)JS";
}

}  // namespace pool::client::test
