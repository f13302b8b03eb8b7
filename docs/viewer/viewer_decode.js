// Reading the lesson's data: window.GI_VIEWER_DATA, set by viewer_data.js, which the
// lesson writes beside this page (its format: lib/gi/radiosity/viewer_data.hpp).
// Numbers come as typed arrays, base64 of little-endian 32-bit values; the
// browsers this page runs on are all little-endian, so the bytes are used as they are.
"use strict";
var GI = window.GI || (window.GI = {});

(function () {

// A typed array of the data: {type, count, base64}, checked against what is expected
// (`per` values per item, `items` items; items omitted: any whole number of them).
GI.typedArray = function (a, type, per, items, what) {
  if (!a || a.type !== type || typeof a.base64 !== "string")
    throw new Error(what + ": expected a " + type + " array");
  const text = atob(a.base64);
  if (text.length !== 4 * a.count) throw new Error(what + ": " + text.length + " bytes for " + a.count + " values");
  if (items !== undefined && a.count !== per * items)
    throw new Error(what + ": " + a.count + " values, expected " + per * items);
  if (a.count % per !== 0) throw new Error(what + ": " + a.count + " values is not a multiple of " + per);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  const kinds = { float32: Float32Array, int32: Int32Array, uint32: Uint32Array };
  return new kinds[type](bytes.buffer);
};

// A run's history as arrays (error is null when measured without a reference).
function readHistory(h, what) {
  const step = GI.typedArray(h.step, "int32", 1, undefined, what + " step");
  const n = step.length;
  const column = (name) => GI.typedArray(h[name], "float32", 1, n, what + " " + name);
  return {
    step: step,
    residual_2: column("residual_2"),
    residual_inf: column("residual_inf"),
    unshot: column("unshot"),
    seconds: column("seconds"),
    error: h.error ? column("error") : null,
  };
}

// A run's frames: one Float32Array of 3 values per element for each, with its step,
// and for progressive refinement the patch that shot and the ambient term.
function readFrames(f, elements, what) {
  const step = GI.typedArray(f.step, "int32", 1, undefined, what + " frame steps");
  const count = step.length;
  const B = GI.typedArray(f.B, "float32", 3 * elements, count, what + " frames");
  const shooter = f.shooter ? GI.typedArray(f.shooter, "int32", 1, count, what + " shooters") : null;
  const ambient = f.ambient ? GI.typedArray(f.ambient, "float32", 3, count, what + " ambient terms") : null;
  const frames = [];
  for (let k = 0; k < count; ++k)
    frames.push({
      step: step[k],
      B: B.subarray(3 * elements * k, 3 * elements * (k + 1)),
      shooter: shooter ? shooter[k] : -1,
      ambient: ambient ? ambient.subarray(3 * k, 3 * k + 3) : null,
    });
  return frames;
}

// The whole data, checked; throws an Error that says what is wrong.
GI.readData = function (raw) {
  if (!raw) throw new Error("no data: viewer_data.js is missing or empty (run the lesson to write it)");
  if (raw.format !== "gi-workbench viewer" || raw.version !== 1)
    throw new Error("viewer_data.js is not format 1 of the gi-workbench viewer");
  const m = raw.mesh;
  const vertices = GI.typedArray(m.vertices, "float32", 3, undefined, "vertices");
  const elements = GI.typedArray(m.elements, "uint32", 4, undefined, "elements");
  const n = elements.length / 4;
  for (let i = 0; i < elements.length; ++i)
    if (elements[i] >= vertices.length / 3) throw new Error("an element's corner is not a vertex");
  const mesh = {
    vertices: vertices,
    elements: elements,
    count: n,
    patch: GI.typedArray(m.element_patch, "int32", 1, n, "element_patch"),
    surface: GI.typedArray(m.element_surface, "int32", 1, n, "element_surface"),
    area: GI.typedArray(m.area, "float32", 1, n, "area"),
    reflectance: GI.typedArray(m.reflectance, "float32", 3, n, "reflectance"),
    emission: GI.typedArray(m.emission, "float32", 3, n, "emission"),
    surfaces: m.surfaces,
  };
  const runs = raw.runs.map((r) => ({
    name: r.name,
    unit: r.unit,
    status: r.status,
    workPerStep: r.work_per_step,
    history: readHistory(r.history, r.name),
    frames: readFrames(r.frames, n, r.name),
  }));
  const lights = raw.lights.map((l) => ({
    name: l.name,
    weight: l.weight,
    B: GI.typedArray(l.B, "float32", 3, n, l.name + " B"),
  }));
  return { lesson: raw.lesson, title: raw.title, exposure: raw.exposure, camera: raw.camera, mesh, runs, lights };
};
})();
