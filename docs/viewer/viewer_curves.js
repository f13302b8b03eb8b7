// Solver curves on a 2D canvas: y on a log scale (residuals and errors fall by
// decades), a vertical line at the step the mesh shows, and under the pointer the
// value of every curve at that x, written also into a text element beside the chart.
"use strict";
var GI = window.GI || (window.GI = {});

(function () {

const palette = ["#1f5fbf", "#d0471a", "#2a9d3a", "#8e44ad", "#b8860b", "#555555"];
const margin = { left: 64, right: 16, top: 14, bottom: 40 };

// Values to label a log axis from lo to hi, at least three where the range allows:
// powers of ten, thinned to about eight; over less than three decades 1-2-5 x 10^k,
// then every digit x 10^k.
function logTicks(lo, hi) {
  const inside = (v) => v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9);
  for (const mantissas of [[1], [1, 2, 5], [1, 2, 3, 4, 5, 6, 7, 8, 9]]) {
    const ticks = [];
    for (let e = Math.floor(Math.log10(lo)); e <= Math.ceil(Math.log10(hi)); ++e)
      mantissas.forEach((m) => { const v = m * Math.pow(10, e); if (inside(v)) ticks.push(v); });
    if (ticks.length >= 3) {
      const every = Math.max(1, Math.ceil(ticks.length / 8));
      return ticks.filter((v, i) => i % every === 0);
    }
  }
  return [lo, hi];
}

// Values to label a linear axis from lo to hi: steps of 1, 2 or 5 x 10^k, at most 6.
function linearTicks(lo, hi) {
  const raw = (hi - lo) / 6, decade = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map((m) => m * decade).find((s) => s >= raw);
  const ticks = [];
  for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step) ticks.push(v);
  return ticks;
}

function format(v) {
  if (!isFinite(v)) return String(v);
  const a = Math.abs(v);
  return a !== 0 && (a < 1e-3 || a >= 1e5) ? v.toExponential(2) : String(+v.toPrecision(4));
}

// series: [{name, x: [], y: []}], drawn in palette order.
GI.Curves = function (canvas, readout) {
  const ctx = canvas.getContext("2d");
  let series = [], labels = { x: "", y: "" }, marker = null, pointer = null, box = null;

  // The index of the point of s nearest to x (xs ascend).
  function nearest(s, x) {
    let lo = 0, hi = s.x.length - 1;
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (s.x[mid] < x) lo = mid; else hi = mid;
    }
    return Math.abs(s.x[lo] - x) <= Math.abs(s.x[hi] - x) ? lo : hi;
  }

  function draw() {
    const w = canvas.width, h = canvas.height;
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, w, h);
    const good = (v) => isFinite(v) && v > 0;
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    series.forEach((s) => s.y.forEach((y, i) => {
      if (!good(y)) return;
      x0 = Math.min(x0, s.x[i]); x1 = Math.max(x1, s.x[i]);
      y0 = Math.min(y0, y); y1 = Math.max(y1, y);
    }));
    ctx.fillStyle = "#111";
    ctx.font = "13px sans-serif";
    if (!(x1 >= x0)) {
      ctx.fillText("no positive values to draw", margin.left, h / 2);
      return;
    }
    if (x1 === x0) x1 = x0 + 1;
    if (y1 <= y0 * 1.0001) { y0 /= 10; y1 *= 10; }
    const ly0 = Math.log10(y0), ly1 = Math.log10(y1);
    box = { x0, x1, px: (x) => margin.left + ((x - x0) / (x1 - x0)) * (w - margin.left - margin.right) };
    const py = (y) => margin.top + ((ly1 - Math.log10(y)) / (ly1 - ly0)) * (h - margin.top - margin.bottom);
    // Axes, decades and labels.
    ctx.strokeStyle = "#ccc";
    ctx.textAlign = "right";
    logTicks(y0, y1).forEach((v) => {
      const y = py(v);
      if (y < margin.top - 1 || y > h - margin.bottom + 1) return;
      ctx.beginPath(); ctx.moveTo(margin.left, y); ctx.lineTo(w - margin.right, y); ctx.stroke();
      ctx.fillText(v.toExponential(0).replace("e+", "e"), margin.left - 6, y + 4);
    });
    ctx.textAlign = "center";
    linearTicks(x0, x1).forEach((v) => {
      const x = box.px(v);
      ctx.beginPath(); ctx.moveTo(x, h - margin.bottom); ctx.lineTo(x, h - margin.bottom + 4); ctx.stroke();
      ctx.fillText(format(v), x, h - margin.bottom + 16);
    });
    ctx.fillText(labels.x, (margin.left + w - margin.right) / 2, h - 6);
    ctx.save();
    ctx.translate(14, (margin.top + h - margin.bottom) / 2);
    ctx.rotate(-Math.PI / 2);
    ctx.fillText(labels.y, 0, 0);
    ctx.restore();
    ctx.strokeStyle = "#333";
    ctx.strokeRect(margin.left, margin.top, w - margin.left - margin.right, h - margin.top - margin.bottom);
    // The curves: breaks where a value cannot be drawn (zero, NaN: a diverging solver).
    series.forEach((s, k) => {
      ctx.strokeStyle = palette[k % palette.length];
      ctx.lineWidth = 2;
      ctx.beginPath();
      let pen = false;
      s.y.forEach((y, i) => {
        if (!good(y)) { pen = false; return; }
        if (pen) ctx.lineTo(box.px(s.x[i]), py(y)); else ctx.moveTo(box.px(s.x[i]), py(y));
        pen = true;
      });
      ctx.stroke();
    });
    ctx.lineWidth = 1;
    // Legend, top right.
    ctx.textAlign = "right";
    series.forEach((s, k) => {
      ctx.fillStyle = palette[k % palette.length];
      ctx.fillText(s.name, w - margin.right - 6, margin.top + 16 * (k + 1));
    });
    const line = (x, colour) => {
      ctx.strokeStyle = colour;
      ctx.beginPath(); ctx.moveTo(box.px(x), margin.top); ctx.lineTo(box.px(x), h - margin.bottom); ctx.stroke();
    };
    if (marker !== null) line(marker, "#e0a000");
    if (pointer !== null) {
      line(pointer, "#888");
      readout.textContent = labels.x + " " + format(pointer) + ": " + series.map((s) => {
        const i = nearest(s, pointer);
        return s.name + " " + format(s.y[i]) + " (at " + format(s.x[i]) + ")";
      }).join("; ");
    }
  }

  canvas.addEventListener("pointermove", (e) => {
    if (!box) return;
    const r = canvas.getBoundingClientRect();
    const px = ((e.clientX - r.left) * canvas.width) / r.width;
    const w = canvas.width - margin.left - margin.right;
    pointer = box.x0 + (Math.max(0, Math.min(w, px - margin.left)) / w) * (box.x1 - box.x0);
    draw();
  });
  canvas.addEventListener("pointerleave", () => { pointer = null; draw(); });

  this.show = function (newSeries, xLabel, yLabel) {
    series = newSeries;
    labels = { x: xLabel, y: yLabel };
    pointer = null;
    readout.textContent = "point at the chart to read the values";
    draw();
  };
  this.mark = function (x) { marker = x; draw(); };
};

})();
