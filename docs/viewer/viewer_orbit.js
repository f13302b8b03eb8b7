// The camera the student orbits: it starts where the lesson's camera stands and
// turns about the point it looks at. Drag to turn, the wheel to move nearer or
// farther, the arrow keys to turn by steps, double-click (or "reset") to go back.
// Matrices are column-major, as WebGL takes them; +y is up, as in every scene.
"use strict";
var GI = window.GI || (window.GI = {});

(function () {

GI.mat4 = {
  multiply(a, b) {
    const m = new Float32Array(16);
    for (let c = 0; c < 4; ++c)
      for (let r = 0; r < 4; ++r) {
        let s = 0;
        for (let k = 0; k < 4; ++k) s += a[k * 4 + r] * b[c * 4 + k];
        m[c * 4 + r] = s;
      }
    return m;
  },
  // The view matrix of a pinhole at `eye` looking at `target`: right = forward x up,
  // so a camera looking along +z sees +x on its left, as the lessons' pictures do.
  lookAt(eye, target, up) {
    const f = normalize(sub(target, eye));
    const s = normalize(cross(f, up));
    const u = cross(s, f);
    return new Float32Array([
      s[0], u[0], -f[0], 0,
      s[1], u[1], -f[1], 0,
      s[2], u[2], -f[2], 0,
      -dot(s, eye), -dot(u, eye), dot(f, eye), 1,
    ]);
  },
  // Perspective projection with the vertical field of view `fov` (degrees).
  perspective(fov, aspect, near, far) {
    const t = 1 / Math.tan((fov * Math.PI) / 360);
    const m = new Float32Array(16);
    m[0] = t / aspect;
    m[5] = t;
    m[10] = (far + near) / (near - far);
    m[11] = -1;
    m[14] = (2 * far * near) / (near - far);
    return m;
  },
};

function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
function normalize(a) { const l = Math.sqrt(dot(a, a)); return [a[0] / l, a[1] / l, a[2] / l]; }

// eye = target + distance (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw)).
GI.Orbit = function (camera, sceneRadius) {
  const target = camera.look_at.slice();
  const start = sub(camera.eye, camera.look_at);
  const startDistance = Math.sqrt(dot(start, start));
  const startYaw = Math.atan2(start[0], start[2]);
  const startPitch = Math.asin(start[1] / startDistance);
  let yaw = startYaw, pitch = startPitch, distance = startDistance;
  const limit = 1.45;  // radians: short of straight up or down, where "up" would flip

  this.reset = () => { yaw = startYaw; pitch = startPitch; distance = startDistance; };
  this.turn = (dYaw, dPitch) => {
    yaw += dYaw;
    pitch = Math.max(-limit, Math.min(limit, pitch + dPitch));
  };
  this.zoom = (factor) => { distance = Math.max(0.05 * startDistance, Math.min(20 * startDistance, distance * factor)); };
  this.eye = () => [
    target[0] + distance * Math.cos(pitch) * Math.sin(yaw),
    target[1] + distance * Math.sin(pitch),
    target[2] + distance * Math.cos(pitch) * Math.cos(yaw),
  ];
  // Projection times view for an image of the given aspect (width / height).
  this.matrix = (aspect) => {
    const near = Math.max(1e-3 * sceneRadius, distance - 2 * sceneRadius, 0.01 * distance);
    const far = distance + 2 * sceneRadius;
    const view = GI.mat4.lookAt(this.eye(), target, [0, 1, 0]);
    return GI.mat4.multiply(GI.mat4.perspective(camera.vertical_fov_degrees, aspect, near, far), view);
  };
};

// Mouse, wheel and keys on `element` turn `orbit`; `changed` redraws.
GI.attachOrbit = function (element, orbit, changed) {
  let last = null;
  element.addEventListener("pointerdown", (e) => {
    last = [e.clientX, e.clientY];
    element.setPointerCapture(e.pointerId);
  });
  element.addEventListener("pointerup", () => { last = null; });
  element.addEventListener("pointermove", (e) => {
    if (!last) return;
    orbit.turn(-0.01 * (e.clientX - last[0]), 0.01 * (e.clientY - last[1]));
    last = [e.clientX, e.clientY];
    changed();
  });
  element.addEventListener("wheel", (e) => {
    e.preventDefault();
    orbit.zoom(Math.exp(0.001 * e.deltaY));
    changed();
  }, { passive: false });
  element.addEventListener("dblclick", () => { orbit.reset(); changed(); });
  element.addEventListener("keydown", (e) => {
    const turns = { ArrowLeft: [0.1, 0], ArrowRight: [-0.1, 0], ArrowUp: [0, -0.1], ArrowDown: [0, 0.1] };
    if (turns[e.key]) {
      orbit.turn(turns[e.key][0], turns[e.key][1]);
    } else if (e.key === "+" || e.key === "-") {
      orbit.zoom(e.key === "+" ? 0.9 : 1.1);
    } else {
      return;
    }
    e.preventDefault();
    changed();
  });
};
})();
