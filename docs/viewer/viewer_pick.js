// Pointing at the mesh: which element lies under a point of the picture, and lines
// drawn over the mesh (the outlines of the nodes a picked leaf gathers from).
//  - picking is done on the CPU, as a ray caster would: every element's corners
//    projected by the same matrix the picture is drawn with, the point tested
//    against its two triangles, the nearest hit (smallest depth) kept;
//  - lines are drawn after the mesh with the depth test on, so a wall hides what is
//    behind it, and a little nearer than the surface they lie on, so that it does not.
"use strict";
var GI = window.GI || (window.GI = {});

(function () {

// The element under the point (x, y) of the view, in normalized device coordinates
// ([-1, 1], y up), drawn with `matrix`; -1 where there is none.
GI.pickElement = function (mesh, matrix, x, y) {
  const project = (v) => {
    const p = [0, 0, 0, 0];
    for (let r = 0; r < 4; ++r)
      p[r] = matrix[r] * mesh.vertices[3 * v] + matrix[4 + r] * mesh.vertices[3 * v + 1] +
             matrix[8 + r] * mesh.vertices[3 * v + 2] + matrix[12 + r];
    return p[3] > 0 ? [p[0] / p[3], p[1] / p[3], p[2] / p[3]] : null;
  };
  // The depth of the triangle abc at the point, if the point lies in it (barycentric weights).
  const depthIn = (a, b, c) => {
    const area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    if (area === 0) return null;
    const u = ((b[0] - x) * (c[1] - y) - (c[0] - x) * (b[1] - y)) / area;
    const v = ((c[0] - x) * (a[1] - y) - (a[0] - x) * (c[1] - y)) / area;
    const w = 1 - u - v;
    return u >= 0 && v >= 0 && w >= 0 ? u * a[2] + v * b[2] + w * c[2] : null;
  };
  let best = -1, nearest = Infinity;
  for (let e = 0; e < mesh.count; ++e) {
    const p = [0, 1, 2, 3].map((c) => project(mesh.elements[4 * e + c]));
    if (p.some((q) => q === null)) continue;  // a corner behind the eye: not in the picture whole
    for (const z of [depthIn(p[0], p[1], p[2]), depthIn(p[0], p[2], p[3])])
      if (z !== null && z >= -1 && z <= 1 && z < nearest) { nearest = z; best = e; }
  }
  return best;
};

// Segments in world space, 2 points each: positions 3 floats a point, colours 4
// (red, green, blue, and alpha: how much of the line covers the picture).
GI.Segments = function () {
  this.positions = [];
  this.colours = [];
};
// The outline of a quadrilateral: its four corners (12 floats from `corners` at `at`).
GI.Segments.prototype.quad = function (corners, at, colour) {
  for (let k = 0; k < 4; ++k)
    for (const c of [k, (k + 1) % 4]) {
      this.positions.push(corners[at + 3 * c], corners[at + 3 * c + 1], corners[at + 3 * c + 2]);
      this.colours.push(colour[0], colour[1], colour[2], colour[3]);
    }
};

// A line is drawn as a thin rectangle of two triangles, 3 pixels wide (WebGL draws
// GL lines one pixel wide only, too thin to see on a projector): each corner is one
// end pushed sideways, and past the end, by half the width in pixels.
const vertexShader = `#version 300 es
in vec3 start, end;
in vec4 colour;
in vec2 corner;           // (0 at the start or 1 at the end, -1 or 1: which side)
uniform mat4 matrix;
uniform vec2 pixel;       // a pixel's size in clip space per unit w
out vec4 shown;
void main() {
  vec4 a = matrix * vec4(start, 1.0), b = matrix * vec4(end, 1.0);
  if (a.w <= 0.0 || b.w <= 0.0) { gl_Position = vec4(2.0, 2.0, 2.0, 1.0); return; }  // behind the eye: not drawn
  vec2 d = (b.xy / b.w - a.xy / a.w) / pixel;  // the line on the screen, in pixels
  vec2 along = length(d) > 0.0 ? normalize(d) : vec2(1.0, 0.0);
  vec2 side = vec2(-along.y, along.x);
  vec4 p = corner.x < 0.5 ? a : b;
  p.xy += 1.5 * ((2.0 * corner.x - 1.0) * along + corner.y * side) * pixel * p.w;
  // A little nearer than the surface it lies on, so that the surface never hides it:
  // 1e-4 of the depth range, about 20 scene units at the Cornell box's back wall,
  // three steps of a 16-bit depth buffer (the least WebGL promises) there.
  p.z -= 1e-4 * p.w;
  gl_Position = p;
  shown = colour;
}`;
const fragmentShader = `#version 300 es
precision highp float;
in vec4 shown;
out vec4 colour;
void main() { colour = shown; }`;

// Draws GI.Segments with `gl`, in their order (the last on top), blended by their
// alpha. Lines test depth against the mesh but do not write it, so a line never
// hides another.
GI.Lines = function (gl, compile) {
  const program = gl.createProgram();
  gl.attachShader(program, compile(gl, gl.VERTEX_SHADER, vertexShader));
  gl.attachShader(program, compile(gl, gl.FRAGMENT_SHADER, fragmentShader));
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error("line shaders: " + gl.getProgramInfoLog(program));
  const vao = gl.createVertexArray(), buffer = gl.createBuffer();
  gl.bindVertexArray(vao);
  gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
  [["start", 3, 0], ["end", 3, 12], ["colour", 4, 24], ["corner", 2, 40]].forEach(([name, size, offset]) => {
    const at = gl.getAttribLocation(program, name);
    gl.enableVertexAttribArray(at);
    gl.vertexAttribPointer(at, size, gl.FLOAT, false, 48, offset);
  });
  gl.bindVertexArray(null);
  const corners = [[0, -1], [1, -1], [1, 1], [0, -1], [1, 1], [0, 1]];  // two triangles

  this.draw = function (segments, matrix, width, height) {
    const count = segments.positions.length / 6;
    if (!count) return;
    const vertices = new Float32Array(6 * 12 * count);
    let at = 0;
    for (let s = 0; s < count; ++s)
      for (const [along, side] of corners) {
        vertices.set(segments.positions.slice(6 * s, 6 * s + 6), at);
        vertices.set(segments.colours.slice(8 * s, 8 * s + 4), at + 6);
        vertices[at + 10] = along, vertices[at + 11] = side;
        at += 12;
      }
    gl.useProgram(program);
    gl.bindVertexArray(vao);
    gl.bindBuffer(gl.ARRAY_BUFFER, buffer);
    gl.bufferData(gl.ARRAY_BUFFER, vertices, gl.DYNAMIC_DRAW);
    gl.uniformMatrix4fv(gl.getUniformLocation(program, "matrix"), false, matrix);
    gl.uniform2f(gl.getUniformLocation(program, "pixel"), 2 / width, 2 / height);
    gl.depthMask(false);
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    gl.drawArrays(gl.TRIANGLES, 0, 6 * count);
    gl.disable(gl.BLEND);
    gl.depthMask(true);
  };
};

})();
