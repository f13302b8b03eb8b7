// Reading the lesson's data: window.GI_VIEWER_DATA, set by viewer_data.js, which the
// lesson writes beside this page (its format: lib/gi/viewer/data.hpp).
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

// Hierarchical radiosity's nodes, links and T-vertices (optional), checked against
// the mesh; also hands the mesh its T-vertices, so that smooth shading has no cracks.
function readHierarchy(h, mesh) {
  const int = (a, per, items, what) => GI.typedArray(a, "int32", per, items, "hierarchy " + what);
  const parent = int(h.nodes.parent, 1, undefined, "parent"), nodes = parent.length;
  const links = h.links, t = h.t_vertices;
  const receiver = int(links.receiver, 1, undefined, "link receivers"), count = receiver.length;
  const out = {
    linksCarry: h.links_carry,
    nodes: {
      count: nodes,
      parent,
      surface: int(h.nodes.surface, 1, nodes, "node surfaces"),
      level: int(h.nodes.level, 1, nodes, "node levels"),
      corners: GI.typedArray(h.nodes.corners, "float32", 12, nodes, "hierarchy node corners"),
    },
    elementNode: int(h.element_node, 1, mesh.count, "element_node"),
    elementGathered: GI.typedArray(h.element_gathered, "float32", 3, mesh.count, "hierarchy element_gathered"),
    links: {
      count,
      receiver,
      source: int(links.source, 1, count, "link sources"),
      F: GI.typedArray(links.F, "float32", 1, count, "hierarchy link F"),
      visibility: GI.typedArray(links.visibility, "float32", 1, count, "hierarchy link visibility"),
      light: GI.typedArray(links.light, "float32", 3, count, "hierarchy link light"),
    },
  };
  const inRange = (a, size) => a.every((i) => i >= 0 && i < size);
  if (!inRange(out.elementNode, nodes) || !inRange(receiver, nodes) || !inRange(out.links.source, nodes) ||
      !parent.every((p, n) => p >= -1 && p < n))
    throw new Error("hierarchy: a node index is out of range");
  const vertex = int(t.vertex, 1, undefined, "T-vertices");
  mesh.tVertices = { vertex, a: int(t.a, 1, vertex.length, "T-vertex ends"), b: int(t.b, 1, vertex.length, "T-vertex ends"),
                     t: GI.typedArray(t.t, "float32", 1, vertex.length, "hierarchy T-vertex t") };
  const vertices = mesh.vertices.length / 3;
  if (![vertex, mesh.tVertices.a, mesh.tVertices.b].every((a) => inRange(a, vertices)))
    throw new Error("hierarchy: a T-vertex is not a vertex");
  return out;
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
  const hierarchy = raw.hierarchy ? readHierarchy(raw.hierarchy, mesh) : null;
  return { lesson: raw.lesson, title: raw.title, exposure: raw.exposure, camera: raw.camera, mesh, runs, lights,
           hierarchy };
};
})();
