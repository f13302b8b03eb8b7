#include "gi/radiosity/hierarchical/balance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "gi/core/onb.hpp"
#include "gi/core/parallel.hpp"
#include "gi/radiosity/hierarchical/exposure.hpp"

namespace gi {

namespace {

// The probe directions, in a frame whose z is the normal: the centres of a 16 x 16 grid
// of cells over the unit square, mapped to the hemisphere so that each cell carries the
// same share of the cosine-weighted view, 1/256 (Malley's method: a point of the disc,
// lifted). Quarter k of a leaf casts the 64 of them whose cell (a, b) has a % 2 and
// b % 2 the bits of k: the four quarters together probe all 256.
std::array<std::vector<vec3>, 4> probe_directions() {
  constexpr int cells = 16;
  std::array<std::vector<vec3>, 4> d;
  for (int b = 0; b < cells; ++b)
    for (int a = 0; a < cells; ++a) {
      const double u = (a + 0.5) / cells, v = (b + 0.5) / cells;
      const double r = std::sqrt(u), phi = 2 * pi * v;
      d[(a % 2) + 2 * (b % 2)].push_back(vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - u)));
    }
  return d;
}

// The links as a matrix on the nodes: for each receiver node, the parts of sources it
// reads (the source, or a source's quarter) with their weights F V (F V_c for a quarter).
// Laid out flat once, so that the sweeps below run through memory in order.
struct Coupling {
  std::vector<int> first;  // node n's entries are [first[n], first[n + 1])
  std::vector<int> part;
  std::vector<double> weight;
};

Coupling coupling_of(const Hierarchy& h) {
  Coupling c;
  std::size_t entries = 0;
  for (const Node& node : h.nodes)
    for (const Link& link : node.links) entries += h.nodes[link.source].leaf() ? 1 : 4;
  c.first.reserve(h.nodes.size() + 1), c.part.reserve(entries), c.weight.reserve(entries);
  for (const Node& node : h.nodes) {
    c.first.push_back(static_cast<int>(c.part.size()));
    for (const Link& link : node.links) {
      const Node& q = h.nodes[link.source];
      if (q.leaf()) {
        c.part.push_back(link.source), c.weight.push_back(link.F * link.visibility);
        continue;
      }
      for (int k = 0; k < 4; ++k)
        if (link.by_quarter[k] > 0) c.part.push_back(q.children[k]), c.weight.push_back(link.F * link.by_quarter[k]);
    }
  }
  c.first.push_back(static_cast<int>(c.part.size()));
  return c;
}

// Row sums sum_q T_pq c_q of every leaf (by node index, into `row`): what is sent pulled
// up the trees (each node the open-area mean of its children's, as the solver pulls
// Node::sent; a node wholly buried sends nothing), gathered, then pushed down, each
// node adding its parent's. Children come after their parent in the vector: a backward
// pass meets them first, a forward one their parents.
void row_sums(const Hierarchy& h, const Coupling& T, const std::vector<double>& c, std::vector<double>& pulled,
              std::vector<double>& row) {
  for (int n = static_cast<int>(h.nodes.size()) - 1; n >= 0; --n) {
    const Node& node = h.nodes[n];
    if (node.open_area <= 0) {
      pulled[n] = 0;
    } else if (node.leaf()) {
      pulled[n] = c[n];
    } else {
      double sum = 0;
      for (int child : node.children) sum += h.nodes[child].open_area * pulled[child];
      pulled[n] = sum / node.open_area;
    }
  }
  for (std::size_t n = 0; n < h.nodes.size(); ++n) {
    double sum = h.nodes[n].parent >= 0 ? row[h.nodes[n].parent] : 0.0;
    for (int e = T.first[n]; e < T.first[n + 1]; ++e) sum += T.weight[e] * pulled[T.part[e]];
    row[n] = sum;
  }
}

// Column sums sum_p a_p r_p T_pq / a_q of every leaf (into `col`): each receiver's sum
// of a r over its leaves, handed through its entries to the parts it reads, spread over
// their open areas, then every node adding what its ancestors were handed.
void column_sums(const Hierarchy& h, const Coupling& T, const std::vector<double>& r, std::vector<double>& R,
                 std::vector<double>& col) {
  std::fill(R.begin(), R.end(), 0.0);  // sum of a_p r_p over the leaves below
  for (int n = static_cast<int>(h.nodes.size()) - 1; n >= 0; --n) {
    const Node& node = h.nodes[n];
    if (node.leaf()) R[n] = node.open_area * r[n];
    if (node.parent >= 0) R[node.parent] += R[n];
  }
  std::fill(col.begin(), col.end(), 0.0);
  for (std::size_t n = 0; n < h.nodes.size(); ++n)
    for (int e = T.first[n]; e < T.first[n + 1]; ++e) col[T.part[e]] += T.weight[e] * R[n];
  for (std::size_t n = 0; n < h.nodes.size(); ++n) {
    const Node& node = h.nodes[n];
    col[n] = node.open_area > 0 ? col[n] / node.open_area : 0.0;
    if (node.parent >= 0) col[n] += col[node.parent];
  }
}

// The largest |scale sum / target - 1| over the leaves that take part.
double largest_error(const std::vector<int>& leaf, const std::vector<double>& sum, const std::vector<double>& scale,
                     const std::vector<double>& target) {
  double worst = 0;
  for (std::size_t k = 0; k < leaf.size(); ++k)
    if (target[k] > 0 && sum[leaf[k]] > 0) worst = std::max(worst, std::abs(scale[leaf[k]] * sum[leaf[k]] / target[k] - 1));
  return worst;
}

// The scale that makes scale * sum = target, over-relaxed: scale^(1 - omega) times
// (target / sum)^omega, a step omega times as long in the logarithm as plain scaling
// takes. Where the sum or the target is 0 there is nothing to balance: 1.
constexpr double omega = 1.2;  // half the sweeps of plain scaling (omega = 1) on the Cornell box
void rescale(const std::vector<int>& leaf, const std::vector<double>& sum, const std::vector<double>& target,
             std::vector<double>& scale) {
  for (std::size_t k = 0; k < leaf.size(); ++k) {
    double& s = scale[leaf[k]];
    s = target[k] > 0 && sum[leaf[k]] > 0 ? std::pow(s, 1 - omega) * std::pow(target[k] / sum[leaf[k]], omega) : 1.0;
  }
}

}  // namespace

bool sees_only_surfaces(const FormFactorScene& blockers, const Hierarchy& h, int leaf) {
  static const std::array<std::vector<vec3>, 4> directions = probe_directions();
  const Node& node = h.nodes[leaf];
  const Onb frame(node.shape.normal);
  const double size = std::sqrt(h.total_area);
  bool probed = false;
  for (int quarter = 0; quarter < 4; ++quarter) {
    // The first open cell of the quarter (exposure.hpp's grid): its centre.
    const int half = exposure_cells / 2;
    int cell = -1;
    for (int k = 0; k < half * half && cell < 0; ++k) {
      const int u = (quarter & 1) * half + k % half, v = (quarter >> 1) * half + k / half;
      if ((node.open >> (exposure_cells * v + u)) & 1) cell = exposure_cells * v + u;
    }
    if (cell < 0) continue;
    probed = true;
    const vec3 x = lifted_point(h, node, (cell % exposure_cells + 0.5) / exposure_cells,
                                (cell / exposure_cells + 0.5) / exposure_cells);
    for (const vec3& d : directions[quarter]) {
      const auto hit = blockers.first_hit(Ray{x, d.x * frame.u + d.y * frame.v + d.z * frame.w, 1e-7 * size});
      if (!hit || !hit->front) return false;  // out of the scene, or onto a back, which reflects nothing
    }
  }
  return probed;
}

Balance balance_links(Hierarchy& h, const FormFactorScene& blockers, int threads, double tolerance, int max_sweeps) {
  const std::vector<int> leaf = leaves(h);
  // The leaves whose view is known: 1, for a leaf that sees only surfaces. Their rows
  // and columns are balanced to it; the others' sums stay as the links have them.
  std::vector<double> target(leaf.size(), 0.0);
  parallel_for(static_cast<int>(leaf.size()), threads, [&](int k) {
    if (h.nodes[leaf[k]].open_area > 0 && sees_only_surfaces(blockers, h, leaf[k])) target[k] = 1;
  });
  const Coupling T = coupling_of(h);
  const std::size_t nodes = h.nodes.size();
  std::vector<double> r(nodes, 1.0), c(nodes, 1.0), row(nodes), col(nodes), work(nodes);
  Balance balance;
  balance.leaves = static_cast<int>(leaf.size());
  for (double t : target) balance.enclosed += t > 0;
  row_sums(h, T, c, work, row);
  column_sums(h, T, r, work, col);
  balance.before = std::max(largest_error(leaf, row, r, target), largest_error(leaf, col, c, target));
  // By turns every row, then every column, scaled towards its target; each moves the
  // other a little, less each sweep. Stopped when neither is off by more than the tolerance.
  for (int sweep = 1; sweep <= max_sweeps; ++sweep) {
    row_sums(h, T, c, work, row);
    const double row_error = largest_error(leaf, row, r, target);
    rescale(leaf, row, target, r);
    column_sums(h, T, r, work, col);
    const double column_error = largest_error(leaf, col, c, target);
    rescale(leaf, col, target, c);
    balance.after = std::max(row_error, column_error);
    balance.sweeps = sweep;
    if (balance.after <= tolerance) break;
  }
  balance.converged = balance.after <= tolerance;
  if (!balance.converged) {
    // Targets no scaling meets (links that disagree about what they see): the links as
    // they are, which every solve before used.
    std::fill(r.begin(), r.end(), 1.0), std::fill(c.begin(), c.end(), 1.0);
    balance.after = balance.before;
  }
  unbalance(h);
  for (int n : leaf) h.nodes[n].gather_scale = r[n], h.nodes[n].send_scale = c[n];
  return balance;
}

void unbalance(Hierarchy& h) {
  for (Node& node : h.nodes) node.gather_scale = node.send_scale = 1;
}

}  // namespace gi
