// Hierarchical radiosity in the viewer (lesson 13): pick a leaf, see the links that
// bring it light. A leaf gathers over its own links and, by push-pull, over every
// ancestor's: light gathered at a node lands on all of it, so on every leaf below
// (push_pull.hpp). The leaf's light is therefore the sum over all those links of
//   light_l = F_l sum_c V_l,c B_c         (before rho; viewer_data.hpp)
// and the solver handed it rho times that (element_gathered). The page lists the
// links by the receiver's level, outlines each link's source on the model, coloured
// by its share of the leaf's light (faint blue: little, yellow: the most), and
// checks the sum against what the solver handed the leaf.
"use strict";
var GI = window.GI || (window.GI = {});

(function () {

const mean = (a, i) => (a[3 * i] + a[3 * i + 1] + a[3 * i + 2]) / 3;
const PICKED = [1, 0, 1, 1];  // the picked leaf's outline: magenta, on no wall of the box
// t: the share against the largest one; blue and faint to yellow and opaque.
const ramp = (t) => [0.1 + 0.9 * t, 0.35 + 0.6 * t, 1 - t, 0.25 + 0.75 * t];

GI.LinkView = function (data, readout) {
  const h = data.hierarchy, mesh = data.mesh, links = h.links;
  const byReceiver = Array.from({ length: h.nodes.count }, () => []);
  for (let l = 0; l < links.count; ++l) byReceiver[links.receiver[l]].push(l);
  let picked = -1;

  // The links of the leaf `element` and of all its ancestors.
  const linksOf = (element) => {
    const out = [];
    for (let n = h.elementNode[element]; n >= 0; n = h.nodes.parent[n]) out.push(...byReceiver[n]);
    return out;
  };
  this.picked = () => picked;

  // The outlines to draw over the mesh: each source by its share, the leaf itself.
  this.segments = () => {
    if (picked < 0) return null;
    const list = linksOf(picked).sort((a, b) => mean(links.light, a) - mean(links.light, b));  // the most last, on top
    const most = list.length ? mean(links.light, list[list.length - 1]) : 0;
    const segments = new GI.Segments();
    for (const l of list) segments.quad(h.nodes.corners, 12 * links.source[l], ramp(most > 0 ? mean(links.light, l) / most : 0));
    segments.quad(h.nodes.corners, 12 * h.elementNode[picked], PICKED);
    return segments;
  };

  const line = (text) => {
    const p = document.createElement("p");
    p.textContent = text;
    return p;
  };
  const colour = (c) => "(" + c.map((x) => x.toPrecision(4)).join(", ") + ")";

  this.pick = (element) => {
    picked = element;
    readout.dataset.element = element;
    if (element < 0) {
      readout.dataset.links = 0;
      readout.replaceChildren(line("Click a leaf to see the links that bring it light."));
      return;
    }
    const list = linksOf(element), leaf = h.elementNode[element];
    readout.dataset.links = list.length;
    const levels = new Map(), sum = [0, 0, 0];
    let total = 0;
    for (const l of list) {
      const level = h.nodes.level[links.receiver[l]];
      levels.set(level, (levels.get(level) || 0) + 1);
      for (let k = 0; k < 3; ++k) sum[k] += links.light[3 * l + k];
      total += mean(links.light, l);
    }
    const name = (node) => "'" + mesh.surfaces[h.nodes.surface[node]] + "' level " + h.nodes.level[node];
    const byLevel = [...levels.keys()].sort((a, b) => b - a)
      .map((level) => levels.get(level) + " at level " + level + (level === h.nodes.level[leaf] ? " (the leaf)" : ""));
    // What the solver handed the leaf, rho taken off (a channel with rho = 0 gathers nothing).
    const handed = [0, 1, 2].map((k) => {
      const rho = mesh.reflectance[3 * element + k];
      return rho > 0 ? h.elementGathered[3 * element + k] / rho : 0;
    });
    const scale = Math.max(...handed.map(Math.abs), 1e-30);
    const off = Math.max(...[0, 1, 2].map((k) => Math.abs(sum[k] - handed[k]))) / scale;
    const rows = list.slice().sort((a, b) => mean(links.light, b) - mean(links.light, a)).slice(0, 5).map((l) => {
      const li = document.createElement("li");
      li.textContent = (total > 0 ? ((100 * mean(links.light, l)) / total).toFixed(1) : "-") + "% from " +
        name(links.source[l]) + " to level " + h.nodes.level[links.receiver[l]] + ": F " +
        links.F[l].toPrecision(3) + ", V " + links.visibility[l].toFixed(2) + ", light " +
        colour(Array.from(links.light.subarray(3 * l, 3 * l + 3)));
      return li;
    });
    const top = document.createElement("ol");
    top.append(...rows);
    readout.replaceChildren(
      line("Element " + element + " is leaf node " + leaf + " on " + name(leaf) + ". " + list.length +
           " links bring it light: " + byLevel.join(", ") + ". They carry " + h.linksCarry + "."),
      line("The largest shares (outlined yellow; faint blue the least):"), top,
      line("Sum over the links of F V B = " + colour(sum) + " W/m^2; the solver handed the leaf rho x " +
           colour(handed) + ": they differ by " + (100 * off).toPrecision(2) + "% (its last iteration's change)."));
  };
  this.pick(-1);
};

})();
