#include "gi/radiosity/hierarchical/hierarchical_solver.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/core/timer.hpp"
#include "gi/radiosity/hierarchical/balance.hpp"
#include "gi/radiosity/hierarchical/exposure.hpp"
#include "gi/radiosity/hierarchical/push_pull.hpp"
#include "gi/report/table.hpp"

namespace gi {

namespace {

// What every node sends along its links: a leaf its B times its send_scale (balance.hpp;
// 1 until the links are balanced), a node above the open-area mean of its children's,
//   sent_p = sum_c A_c sent_c / sum_c A_c
// and a node wholly buried nothing.
void pull_sent(Hierarchy& h) {
  // Children come after their parent in the vector: backwards, a node's children are done before it.
  for (int n = static_cast<int>(h.nodes.size()) - 1; n >= 0; --n) {
    Node& node = h.nodes[n];
    if (node.open_area <= 0) {
      node.sent = Color(0.0);  // wholly buried: it holds no light to send
      continue;
    }
    if (node.leaf()) {
      node.sent = node.send_scale * node.B;
      continue;
    }
    Color sum(0.0);
    for (int child : node.children) sum += h.nodes[child].open_area * h.nodes[child].sent;
    node.sent = sum / node.open_area;
  }
}

// One step: pull what every node sends, gather over every node, in parallel blocks
// (each node writes its own), then push-pull down every surface's tree.
void iterate(Hierarchy& h, int threads) {
  pull_sent(h);
  std::vector<Color> sent(h.nodes.size());
  for (std::size_t n = 0; n < h.nodes.size(); ++n) sent[n] = h.nodes[n].sent;
  constexpr int block = 512;
  const int blocks = static_cast<int>((h.nodes.size() + block - 1) / block);
  parallel_for(blocks, threads, [&](int b) {
    const std::size_t end = std::min(h.nodes.size(), static_cast<std::size_t>(b + 1) * block);
    for (std::size_t n = static_cast<std::size_t>(b) * block; n < end; ++n) h.nodes[n].gathered = gather(h, h.nodes[n], sent);
  });
  for (int root = 0; root < static_cast<int>(h.surfaces.size()); ++root) push_pull(h, root, Color(0.0));
}

// sqrt(sum A (a - b)^2 / sum A b^2) over the leaves, channels summed.
double relative_change(const Hierarchy& h, const std::vector<int>& leaf, const std::vector<Color>& before) {
  double d2 = 0, b2 = 0;
  for (std::size_t k = 0; k < leaf.size(); ++k) {
    const Node& node = h.nodes[leaf[k]];
    d2 += node.shape.area * length_squared(node.B - before[k]);
    b2 += node.shape.area * length_squared(node.B);
  }
  return b2 > 0 ? std::sqrt(d2 / b2) : std::sqrt(d2);
}

std::vector<Color> radiosity_of(const Hierarchy& h, const std::vector<int>& leaf) {
  std::vector<Color> B;
  B.reserve(leaf.size());
  for (int n : leaf) B.push_back(h.nodes[n].B);
  return B;
}

// D of a leaf's open part (exposure.hpp). A leaf at a block's foot sends on the light
// of its open part only (push-pull's B is the open part's), and a mean over its buried
// part as well handed the block's faces a dark floor at their feet (docs/13). So a leaf
// not wholly open is lit cell by open cell, each cell's D weighted by its area.
Color open_direct_light(const Hierarchy& h, const Node& node, const DirectLighting& lights,
                        const FormFactorScene& blockers, int points) {
  if (node.open == 0xFFFF || node.open == 0) return direct_radiosity(lights, blockers, node.shape, node.rho, points);
  constexpr double side = 1.0 / exposure_cells;
  Color sum(0.0);
  double area = 0;
  for (int v = 0; v < exposure_cells; ++v)
    for (int u = 0; u < exposure_cells; ++u) {
      if (!((node.open >> (exposure_cells * v + u)) & 1)) continue;
      const double s0 = u * side, s1 = s0 + side, t0 = v * side, t1 = t0 + side;
      const Polygon cell = make_polygon({node_point(h, node, s0, t0), node_point(h, node, s1, t0),
                                         node_point(h, node, s1, t1), node_point(h, node, s0, t1)});
      sum += cell.area * direct_radiosity(lights, blockers, cell, node.rho, points);
      area += cell.area;
    }
  return sum / area;
}

// exact_direct: every leaf's source term becomes its direct light D (the source term
// of the indirect system); a leaf keeps its D once computed (`known`, by node).
void set_direct_light(Hierarchy& h, const DirectLighting& lights, const FormFactorScene& blockers,
                      const DirectLightSettings& settings, std::vector<char>& known, int threads) {
  const std::vector<int> leaf = leaves(h);
  known.resize(h.nodes.size(), 0);
  parallel_for(static_cast<int>(leaf.size()), threads, [&](int k) {
    Node& node = h.nodes[leaf[k]];
    if (!known[leaf[k]]) node.source = open_direct_light(h, node, lights, blockers, settings.receiver_points);
  });
  for (int n : leaf) known[n] = 1;
  // BF-refinement's scale is the largest source term of the system solved: here D's.
  h.largest_emission = 0;
  for (int n : leaf) h.largest_emission = std::max(h.largest_emission, max_component(h.nodes[n].source));
}

}  // namespace

void check(const HierarchicalSettings& s) {
  check(s.refinement);
  if (!(s.tolerance > 0 && s.tolerance < 1)) throw std::invalid_argument("hierarchical radiosity: the tolerance must lie in (0, 1)");
  if (!(s.refining_tolerance > 0 && s.refining_tolerance < 1))
    throw std::invalid_argument("hierarchical radiosity: the refining tolerance must lie in (0, 1)");
  if (s.max_iterations < 1 || s.max_iterations > 1'000'000)
    throw std::invalid_argument("hierarchical radiosity: max iterations must lie in [1, 10^6]");
  if (s.max_rounds < 0 || s.max_rounds > 1000) throw std::invalid_argument("hierarchical radiosity: max rounds must lie in [0, 1000]");
  if (s.exact_direct) check(s.direct);
}

std::vector<Color> leaf_radiosity(const Hierarchy& h) { return radiosity_of(h, leaves(h)); }

std::string describe(const BalancedSolve& b) {
  const auto number = [](double x, int digits, Format format) { return format_number(x, digits, format); };
  const Balance& a = b.balance;
  return "balanced: " + std::to_string(a.enclosed) + " of " + std::to_string(a.leaves) +
         " leaves see only surfaces; their sums " + number(100 * a.before, 1, Format::Fixed) + "% off, " +
         (a.converged ? number(a.after, 0, Format::Scientific) + " after " + std::to_string(a.sweeps) + " sweeps"
                      : "not balanced after " + std::to_string(a.sweeps) + " sweeps (left as they are)") +
         " (" + number(1e3 * b.balance_seconds, 0, Format::Fixed) + " ms); then " + std::to_string(b.iterations) +
         " iterations (" + number(1e3 * b.solve_seconds, 0, Format::Fixed) + " ms), B moved by " +
         number(b.change, 1, Format::Scientific);
}

SolverResult solve_links(Hierarchy& h, const SolverOptions& options, int threads) {
  const std::vector<int> leaf = leaves(h);
  if (options.reference && options.reference->size() != leaf.size())
    throw std::invalid_argument("hierarchical solve: the reference must hold one B per leaf");
  // The leaves as the monitor of every solver sees a system: their open areas (the
  // light a leaf holds is its open part's), reflectances and source terms; no matrix,
  // the links are it. So every column of the history means what it means for Jacobi.
  RadiositySystem system;
  for (int n : leaf) {
    system.area.push_back(h.nodes[n].open_area);
    system.rho.push_back(h.nodes[n].rho);
    system.emission.push_back(h.nodes[n].source);
  }
  SolverMonitor monitor("hierarchical", system, options);
  // Step k records B_k = (gather, push-pull)^k of the B there, with its residual
  // r_k = E + T B_k - B_k, which is what the next iteration adds: B_k+1 - B_k. So each
  // step's residual costs no extra pass, and the solve ends one iteration past the B
  // it returns, which the nodes are set back to.
  iterate(h, threads);
  std::vector<Color> B, r(leaf.size()), nodes_B(h.nodes.size());
  for (int step = 1;; ++step) {
    B = radiosity_of(h, leaf);
    for (std::size_t n = 0; n < h.nodes.size(); ++n) nodes_B[n] = h.nodes[n].B;
    iterate(h, threads);
    for (std::size_t k = 0; k < leaf.size(); ++k) r[k] = h.nodes[leaf[k]].B - B[k];
    if (monitor.stop_after(step, B, r)) break;
  }
  for (std::size_t n = 0; n < h.nodes.size(); ++n) h.nodes[n].B = nodes_B[n];
  return monitor.finish(std::move(B), std::move(r));
}

HierarchicalResult solve_hierarchical(Hierarchy& h, const FormFactorScene& blockers, const HierarchicalSettings& s,
                                      int threads) {
  check(s);
  HierarchicalResult result;
  SolverResult& all = result.solution;
  all.method = "hierarchical";
  SolverOptions options;
  options.max_steps = s.max_iterations;
  const Timer clock;
  // A solve's history numbered on from the last, timed from the start.
  const auto record = [&](SolverResult solve, double start) {
    const int before = all.history.empty() ? 0 : all.history.back().step;
    for (SolverStep step : solve.history) {
      step.step += before;
      step.seconds += start;
      all.history.push_back(step);
    }
    all.B = std::move(solve.B);
    all.residual = std::move(solve.residual);
    all.status = solve.status;
  };
  bool settled = false;
  std::vector<char> known;  // exact_direct: the leaves whose D is set
  std::optional<DirectLighting> lights;
  if (s.exact_direct) {
    lights.emplace(make_mesh(h.surfaces, {1e300, 1}), s.direct.light_cells);
    for (Node& node : h.nodes) node.source = node.B = Color(0.0);  // B' before any light has bounced
  }
  unbalance(h);  // the links are balanced once they are all refined
  options.tolerance = s.refining_tolerance;
  for (int round = 0; round <= s.max_rounds; ++round) {
    RefinementRound row;
    row.round = round;
    const Timer refine_timer;
    const RefinementCount count = round == 0 && link_count(h) == 0 ? link_surfaces(h, blockers, s.refinement, threads)
                                                                   : refine_links(h, blockers, s.refinement, threads);
    row.refine_seconds = refine_timer.seconds();
    if (round > 0 && count.replaced == 0) {
      settled = true;
      break;
    }
    if (s.exact_direct) set_direct_light(h, *lights, blockers, s.direct, known, threads);
    const std::vector<int> leaf = leaves(h);
    const std::vector<Color> before = radiosity_of(h, leaf);
    const double start = clock.seconds();
    SolverResult solve = solve_links(h, options, threads);
    row.solve_seconds = solve.history.back().seconds;
    row.nodes = static_cast<int>(h.nodes.size());
    row.leaves = static_cast<int>(leaf.size());
    row.links = link_count(h);
    row.evaluated = count.evaluated;
    row.replaced = count.replaced;
    row.iterations = solve.history.back().step;
    row.change = relative_change(h, leaf, before);
    result.rounds.push_back(row);
    record(std::move(solve), start);
    if (all.status == SolveStatus::Diverged) return result;
  }
  // The links as they will stay: balanced, and solved to the tolerance from the B there.
  {
    BalancedSolve& last = result.balanced;
    const Timer balance_timer;
    last.balance = balance_links(h, blockers, threads);
    last.balance_seconds = balance_timer.seconds();
    const std::vector<int> leaf = leaves(h);
    const std::vector<Color> before = radiosity_of(h, leaf);
    options.tolerance = s.tolerance;
    const double start = clock.seconds();
    SolverResult solve = solve_links(h, options, threads);
    last.solve_seconds = solve.history.back().seconds;
    last.iterations = solve.history.back().step;
    last.change = relative_change(h, leaf, before);
    record(std::move(solve), start);
    if (all.status == SolveStatus::Diverged) return result;
  }
  if (all.status == SolveStatus::Converged && !settled) all.status = SolveStatus::StoppedAtLimit;
  if (s.exact_direct) {
    const std::vector<int> leaf = leaves(h);
    for (std::size_t k = 0; k < leaf.size(); ++k) {
      result.direct.push_back(h.nodes[leaf[k]].source);
      all.B[k] += h.surfaces[h.nodes[leaf[k]].surface].emission;  // B = E + B'
    }
  }
  return result;
}

}  // namespace gi
