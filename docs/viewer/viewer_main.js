// The viewer page: what the lesson recorded (GI.readData), shown as
//  - the solver step by step: a slider over the recorded steps; the runs that have
//    frames side by side, each at the same work (for shooting, the patch that shot
//    in the step is outlined in yellow); their curves beside, the step marked;
//  - relighting: a slider per light, the mesh showing B = sum_l w_l B_l, where B_l
//    solves (I - RF) B = E_l for light l alone: the system is linear in E;
//  - hierarchical radiosity (data.hierarchy): a click picks a leaf, and the links
//    that bring it light are outlined and listed (viewer_links.js).
"use strict";
var GI = window.GI || (window.GI = {});

(function () {

const $ = (id) => document.getElementById(id);

function start() {
  let data;
  try {
    data = GI.readData(window.GI_VIEWER_DATA);
  } catch (e) {
    $("problem").textContent = "Cannot show this lesson's data: " + e.message;
    $("problem").hidden = false;
    return;
  }
  document.title = data.lesson + ": " + data.title;
  $("title").textContent = data.title;
  $("lesson").textContent = "lesson " + data.lesson + ", " + data.mesh.count + " elements";

  // The runs drawn: those with steps to replay, side by side; else the first one's
  // final solution. The slider runs over the frames of the one with the most.
  const replayed = data.runs.filter((r) => r.frames.length > 1);
  const drawn = replayed.length ? replayed : data.runs.filter((r) => r.frames.length).slice(0, 1);
  const primary = drawn.reduce((a, r) => (r.frames.length > a.frames.length ? r : a), drawn[0] || null);
  const state = {
    mode: drawn.length ? "runs" : "lights",
    frame: primary ? primary.frames.length - 1 : 0,  // opens on the last frame, the solution; play replays
    exposure: data.exposure,
    weights: data.lights.map((l) => l.weight),
  };

  const canvas = $("mesh");
  const view = new GI.MeshView(canvas, data.mesh);
  const orbit = new GI.Orbit(data.camera, GI.meshRadius(data.mesh));
  const curves = new GI.Curves($("curves"), $("readout"));
  const linkView = data.hierarchy ? new GI.LinkView(data, $("links")) : null;
  $("links").hidden = !linkView;
  if (linkView) $("outline-name").textContent = "leaf outlines (the mesh the oracle made)";

  // The frame of `run` with the most work done not beyond `work` (its first if none).
  function frameAt(run, work) {
    let best = run.frames[0];
    for (const f of run.frames) if (f.step * run.workPerStep <= work * (1 + 1e-9)) best = f;
    return best;
  }
  // What the mesh shows of a frame: B, or B + rho * ambient (progressive.hpp).
  function shownB(frame) {
    if (!$("ambient").checked || !frame.ambient) return frame.B;
    const B = new Float32Array(frame.B.length), rho = data.mesh.reflectance;
    for (let i = 0; i < B.length; ++i) B[i] = frame.B[i] + rho[i] * frame.ambient[i % 3];
    return B;
  }
  function relit() {
    const B = new Float32Array(3 * data.mesh.count);
    data.lights.forEach((l, k) => { for (let i = 0; i < B.length; ++i) B[i] += state.weights[k] * l.B[i]; });
    return B;
  }

  function draw() {
    const smooth = $("smooth").checked;
    let views = [], labels = [];
    if (state.mode === "lights") {
      views = [{ B: relit(), smooth, marked: -1 }];
      labels = ["B = " + data.lights.map((l, k) => state.weights[k].toFixed(2) + " B(" + l.name + ")").join(" + ")];
    } else {
      const current = primary.frames[state.frame];
      const work = current.step * primary.workPerStep;
      for (const run of drawn) {
        const f = run === primary ? current : frameAt(run, work);
        views.push({ B: shownB(f), smooth, marked: f.shooter });
        labels.push(run.name + ", " + run.unit + " " + f.step + (f.shooter >= 0 ? " (patch " + f.shooter + " shot)" : ""));
      }
      $("step-label").textContent = primary.unit + " " + current.step + " (frame " + (state.frame + 1) + " of " +
                                    primary.frames.length + ")";
      curves.mark(markerX(current));
    }
    if (linkView && views.length === 1) views[0].lines = linkView.segments();
    const size = views.length === 1 ? 480 : Math.max(240, Math.floor(960 / views.length));
    if (canvas.width !== size * views.length) canvas.width = size * views.length;
    if (canvas.height !== size) canvas.height = size;
    view.draw(views, orbit, state.exposure, $("outline").checked);
    $("view-labels").replaceChildren(...labels.map((text) => {
      const span = document.createElement("span");
      span.textContent = text;
      return span;
    }));
    $("view-labels").style.width = canvas.width + "px";
  }

  // The chart: one curve per run, y and x as chosen.
  const quantities = {
    unshot: "unshot energy / emitted",
    error: "RMS error / RMS reference",
    residual_2: "||r||_2 / ||E||_2",
    residual_inf: "max |r_i| / max E",
  };
  const axes = { step: (primary ? primary.unit : "step") + "s", work: "sweeps of work (n^2 multiply-adds)",
                 seconds: "solver time (ms)" };
  const x = (run, i) => {
    const h = run.history, axis = $("x-axis").value;
    return axis === "step" ? h.step[i] : axis === "work" ? h.step[i] * run.workPerStep : 1e3 * h.seconds[i];
  };
  function markerX(frame) {
    const axis = $("x-axis").value, h = primary.history;
    if (axis === "step") return frame.step;
    if (axis === "work") return frame.step * primary.workPerStep;
    let i = 0;
    while (i + 1 < h.step.length && h.step[i] < frame.step) ++i;
    return 1e3 * h.seconds[i];
  }
  function chart() {
    const y = $("y-axis").value;
    curves.show(data.runs.filter((r) => r.history[y]).map((r) => ({
      name: r.name,
      x: Array.from(r.history.step, (_, i) => x(r, i)),
      y: Array.from(r.history[y]),
    })), axes[$("x-axis").value], quantities[y]);
    if (state.mode === "runs" && primary) curves.mark(markerX(primary.frames[state.frame]));
  }
  const options = (select, entries, chosen) => {
    select.replaceChildren(...entries.map(([value, text]) => new Option(text, value, value === chosen, value === chosen)));
  };
  const shooting = data.runs.some((r) => r.unit === "shot");
  const withError = data.runs.some((r) => r.history.error);
  options($("y-axis"), Object.entries(quantities).filter(([k]) => k !== "error" || withError),
          shooting ? "unshot" : withError ? "error" : "residual_2");
  const sameWork = data.runs.every((r) => r.workPerStep === data.runs[0].workPerStep);
  // A hierarchical iteration is a pass over the links, not a sweep of n^2: no work axis.
  options($("x-axis"), Object.entries(axes).filter(([k]) => k !== "work" || !data.hierarchy), sameWork ? "step" : "work");
  $("y-axis").addEventListener("change", chart);
  $("x-axis").addEventListener("change", chart);

  // Controls.
  const slider = $("step");
  slider.max = primary ? primary.frames.length - 1 : 0;
  slider.value = state.frame;
  const last = () => !primary || state.frame >= primary.frames.length - 1;
  const playLabel = () => { $("play").textContent = playing ? "pause" : last() ? "replay from the start" : "play"; };
  slider.addEventListener("input", () => { state.frame = +slider.value; playLabel(); draw(); });
  $("step-row").hidden = !primary || primary.frames.length < 2;
  let playing = null;
  $("play").addEventListener("click", () => {
    if (playing) { clearInterval(playing); playing = null; playLabel(); return; }
    if (last()) state.frame = 0;
    playing = setInterval(() => {
      if (last()) { $("play").click(); return; }
      slider.value = ++state.frame;
      draw();
    }, 150);
    playLabel();
  });
  playLabel();
  const exposureLabel = () => { $("exposure-label").textContent = state.exposure.toPrecision(3); };
  $("exposure").value = Math.log2(state.exposure);
  $("exposure").addEventListener("input", () => { state.exposure = Math.pow(2, +$("exposure").value); exposureLabel(); draw(); });
  exposureLabel();
  ["smooth", "outline", "ambient"].forEach((id) => $(id).addEventListener("change", draw));
  $("ambient-row").hidden = !drawn.some((r) => r.frames.some((f) => f.ambient));
  $("reset").addEventListener("click", () => { orbit.reset(); draw(); });
  GI.attachOrbit(canvas, orbit, draw);
  // A click that did not turn the camera picks the leaf under the pointer.
  let down = null;
  canvas.addEventListener("pointerdown", (e) => { down = [e.clientX, e.clientY]; });
  canvas.addEventListener("click", (e) => {
    if (!linkView || !down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 3) return;
    const box = canvas.getBoundingClientRect();
    const x = e.clientX - box.left - canvas.clientLeft, y = e.clientY - box.top - canvas.clientTop;
    const matrix = orbit.matrix(canvas.width / canvas.height);
    GI.pickLeaf(GI.pickElement(data.mesh, matrix, (2 * x) / canvas.clientWidth - 1, 1 - (2 * y) / canvas.clientHeight));
  });
  GI.pickLeaf = (element) => { linkView.pick(element); draw(); };  // also the browser test's way in

  data.lights.forEach((light, k) => {
    const label = document.createElement("label"), input = document.createElement("input"), value = document.createElement("span");
    Object.assign(input, { type: "range", min: 0, max: 2, step: 0.01, value: light.weight, id: "light-" + k });
    value.textContent = light.weight.toFixed(2);
    input.addEventListener("input", () => { state.weights[k] = +input.value; value.textContent = state.weights[k].toFixed(2); draw(); });
    label.append(light.name + " ", input, " ", value);
    $("lights").append(label);
  });
  const setMode = (mode) => {
    state.mode = mode;
    $("lights").hidden = mode !== "lights";
    $("step-row").hidden = mode !== "runs" || !primary || primary.frames.length < 2;
    draw();
  };
  $("mode-row").hidden = !(drawn.length && data.lights.length);
  document.querySelectorAll("input[name=mode]").forEach((r) => r.addEventListener("change", () => setMode(r.value)));

  // Each run's status and where it ended: "stopped at the limit after 800 shots" alone
  // reads as a failure, though the run did what it was asked.
  const ending = (r) => {
    const last = (q) => (r.history[q] && r.history[q].length ? r.history[q][r.history[q].length - 1] : null);
    const unshot = last("unshot"), error = last("error"), residual = last("residual_2");
    const short = (v) => (v !== 0 && (v < 1e-3 || v >= 1e5) ? v.toExponential(1) : String(+v.toPrecision(3)));
    if (unshot !== null) return ": unshot energy " + short(unshot) + " of the emitted";
    if (error !== null) return ": RMS error " + short(error) + " of the reference's";
    if (residual !== null) return ": residual " + short(residual) + " of ||E||";
    return "";
  };
  $("statuses").replaceChildren(...data.runs.map((r) => {
    const li = document.createElement("li");
    li.textContent = r.name + ": " + r.status + ending(r);
    return li;
  }));
  chart();
  setMode(state.mode);
  document.body.dataset.ready = "yes";  // for the browser test: the first picture is drawn
}

try {
  start();
} catch (e) {
  $("problem").textContent = "The viewer failed: " + e.message;
  $("problem").hidden = false;
  throw e;
}

})();
