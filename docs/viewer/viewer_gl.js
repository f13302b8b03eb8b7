// Drawing the radiosity mesh with WebGL2, as the lessons' display does
// (lib/gi/radiosity/display/display.hpp): every element a quadrilateral showing the radiance
// L = B / pi, times the exposure, clamped to [0, 1] and sRGB-encoded.
//   flat    each element one colour, its own B
//   smooth  Gouraud's: each vertex the area-weighted mean of the elements that share
//           it, B_v = sum_e A_e B_e / sum_e A_e (vertex_colours.hpp), and the four
//           corners blended bilinearly across the element; where the mesh has
//           T-vertices (hierarchical radiosity's leaves, leaf_mesh.hpp), each takes
//           the value the larger element's edge has there, B_v = (1 - t) B_a + t B_b,
//           so that both sides of the edge show the same colours: no crack
// Backs of surfaces are dark grey (the lessons draw them black) so that the box can
// be told from the void when the camera orbits outside it.
"use strict";
var GI = window.GI || (window.GI = {});

(function () {

const vertexShader = `#version 300 es
in vec3 position;
in vec2 corner;           // (0,0) (1,0) (1,1) (0,1): where this vertex is on its element
in vec3 c0, c1, c2, c3;   // the element's four corner radiosities, the same at its four vertices
in float mark;            // 1 on the patch that shoots in this step
uniform mat4 matrix;
out vec2 st;
flat out vec3 b0, b1, b2, b3;
flat out float marked;
void main() {
  st = corner;
  b0 = c0; b1 = c1; b2 = c2; b3 = c3;
  marked = mark;
  gl_Position = matrix * vec4(position, 1.0);
}`;

const fragmentShader = `#version 300 es
precision highp float;
in vec2 st;
flat in vec3 b0, b1, b2, b3;
flat in float marked;
uniform float exposure;
uniform bool outline;     // draw every element's edges
out vec4 colour;
vec3 srgb(vec3 c) {
  return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
  if (!gl_FrontFacing) { colour = vec4(0.12, 0.12, 0.12, 1.0); return; }
  // B(s, t) = (1-s)(1-t) B0 + s(1-t) B1 + s t B2 + (1-s) t B3, then L = B / pi
  vec3 B = (1.0 - st.x) * (1.0 - st.y) * b0 + st.x * (1.0 - st.y) * b1 + st.x * st.y * b2 + (1.0 - st.x) * st.y * b3;
  vec3 shown = srgb(clamp(exposure * B / 3.14159265358979, 0.0, 1.0));
  float edge = min(min(st.x, 1.0 - st.x), min(st.y, 1.0 - st.y));
  float width = fwidth(edge) * 1.2;
  if (outline && edge < width) shown = mix(shown, vec3(0.0), 0.6);
  if (marked > 0.5) shown = edge < 3.0 * width ? vec3(1.0, 0.8, 0.0) : mix(shown, vec3(1.0, 0.85, 0.2), 0.45);
  colour = vec4(shown, 1.0);
}`;

function compile(gl, type, source) {
  const shader = gl.createShader(type);
  gl.shaderSource(shader, source);
  gl.compileShader(shader);
  if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS)) throw new Error("shader: " + gl.getShaderInfoLog(shader));
  return shader;
}

// B per vertex, the area-weighted mean of the elements at it (vertex_colours.hpp),
// then the T-vertices from their edges, coarsest first (leaf_vertex_radiosity).
function vertexRadiosity(mesh, B) {
  const sum = new Float64Array(mesh.vertices.length), weight = new Float64Array(mesh.vertices.length / 3);
  for (let e = 0; e < mesh.count; ++e)
    for (let c = 0; c < 4; ++c) {
      const v = mesh.elements[4 * e + c];
      for (let k = 0; k < 3; ++k) sum[3 * v + k] += mesh.area[e] * B[3 * e + k];
      weight[v] += mesh.area[e];
    }
  for (let v = 0; v < weight.length; ++v)
    for (let k = 0; k < 3; ++k) sum[3 * v + k] = weight[v] > 0 ? sum[3 * v + k] / weight[v] : 0;
  const tv = mesh.tVertices;
  for (let i = 0; tv && i < tv.vertex.length; ++i)
    for (let k = 0; k < 3; ++k)
      sum[3 * tv.vertex[i] + k] = (1 - tv.t[i]) * sum[3 * tv.a[i] + k] + tv.t[i] * sum[3 * tv.b[i] + k];
  return sum;
}

// One WebGL2 canvas showing `mesh` in one or more viewports side by side.
GI.MeshView = function (canvas, mesh) {
  const gl = canvas.getContext("webgl2", { antialias: true, preserveDrawingBuffer: true });
  if (!gl) throw new Error("this browser offers no WebGL2: the viewer needs it to draw the mesh");
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, vertexShader));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, fragmentShader));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error("shaders: " + gl.getProgramInfoLog(program));

  // Four vertices of its own per element (so that an element can be flat), two
  // triangles 0-1-2 and 0-2-3, counter-clockwise from the lit side as the corners are.
  const n = mesh.count;
  const positions = new Float32Array(12 * n), corners = new Float32Array(8 * n);
  const indices = new Uint32Array(6 * n);
  const unit = [0, 0, 1, 0, 1, 1, 0, 1];
  for (let e = 0; e < n; ++e) {
    for (let c = 0; c < 4; ++c) {
      const v = mesh.elements[4 * e + c];
      positions.set(mesh.vertices.subarray(3 * v, 3 * v + 3), 12 * e + 3 * c);
    }
    corners.set(unit, 8 * e);
    indices.set([4 * e, 4 * e + 1, 4 * e + 2, 4 * e, 4 * e + 2, 4 * e + 3], 6 * e);
  }
  const buffer = (target, data) => {
    const b = gl.createBuffer();
    gl.bindBuffer(target, b);
    gl.bufferData(target, data, gl.STATIC_DRAW);
    return b;
  };
  const attribute = (name, b, size, stride, offset) => {
    const at = gl.getAttribLocation(program, name);
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.enableVertexAttribArray(at);
    gl.vertexAttribPointer(at, size, gl.FLOAT, false, stride, offset);
  };
  const vao = gl.createVertexArray();
  gl.bindVertexArray(vao);
  attribute("position", buffer(gl.ARRAY_BUFFER, positions), 3, 0, 0);
  attribute("corner", buffer(gl.ARRAY_BUFFER, corners), 2, 0, 0);
  buffer(gl.ELEMENT_ARRAY_BUFFER, indices);
  const colourBuffer = gl.createBuffer();  // per vertex: c0 c1 c2 c3 mark, 13 floats
  ["c0", "c1", "c2", "c3"].forEach((name, k) => attribute(name, colourBuffer, 3, 52, 12 * k));
  attribute("mark", colourBuffer, 1, 52, 48);
  const colours = new Float32Array(52 * n);
  const lines = new GI.Lines(gl, compile);  // viewer_pick.js

  // The colours of one view: B per element, smooth or flat, and the patch to mark (-1: none).
  function fill(B, smooth, markedPatch) {
    const vertexB = smooth ? vertexRadiosity(mesh, B) : null;
    for (let e = 0; e < n; ++e) {
      const at = 52 * e;
      for (let c = 0; c < 4; ++c) {
        const v = mesh.elements[4 * e + c];
        for (let k = 0; k < 3; ++k) colours[at + 3 * c + k] = smooth ? vertexB[3 * v + k] : B[3 * e + k];
      }
      colours[at + 12] = mesh.patch[e] === markedPatch ? 1 : 0;
      for (let c = 1; c < 4; ++c) colours.copyWithin(at + 13 * c, at, at + 13);
    }
    gl.bindBuffer(gl.ARRAY_BUFFER, colourBuffer);
    gl.bufferData(gl.ARRAY_BUFFER, colours, gl.DYNAMIC_DRAW);
  }

  // Draws views side by side: each {B, smooth, marked, lines (GI.Segments, optional)}
  // in an equal share of the width.
  this.draw = function (views, orbit, exposure, outline) {
    gl.viewport(0, 0, canvas.width, canvas.height);
    gl.clearColor(0, 0, 0, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.useProgram(program);
    gl.bindVertexArray(vao);
    gl.uniform1f(gl.getUniformLocation(program, "exposure"), exposure);
    gl.uniform1i(gl.getUniformLocation(program, "outline"), outline ? 1 : 0);
    const width = Math.floor(canvas.width / views.length);
    views.forEach((view, i) => {
      fill(view.B, view.smooth, view.marked);
      gl.viewport(i * width, 0, width, canvas.height);
      const matrix = orbit.matrix(width / canvas.height);
      gl.uniformMatrix4fv(gl.getUniformLocation(program, "matrix"), false, matrix);
      gl.drawElements(gl.TRIANGLES, 6 * n, gl.UNSIGNED_INT, 0);
      if (!view.lines) return;
      lines.draw(view.lines, matrix, width, canvas.height);
      gl.useProgram(program);
      gl.bindVertexArray(vao);
    });
  };
};

// The radius of a sphere about the mesh's centre holding every vertex.
GI.meshRadius = function (mesh) {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < mesh.vertices.length; ++i) {
    lo[i % 3] = Math.min(lo[i % 3], mesh.vertices[i]);
    hi[i % 3] = Math.max(hi[i % 3], mesh.vertices[i]);
  }
  return 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
};

})();
