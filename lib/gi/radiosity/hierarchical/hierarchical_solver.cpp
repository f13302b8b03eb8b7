#include "gi/radiosity/hierarchical/hierarchical_solver.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>

#include "gi/core/parallel.hpp"
#include "gi/core/timer.hpp"
#include "gi/radiosity/hierarchical/exposure.hpp"
#include "gi/radiosity/hierarchical/push_pull.hpp"

namespace gi {

namespace {

double mean(const Color& c) { return (c.x + c.y + c.z) / 3; }

// One gather over every node, in parallel blocks (each node writes its own), then
// push-pull down every surface's tree.
void iterate(Hierarchy& h, int threads) {
  std::vector<Color> B(h.nodes.size());
  for (std::size_t n = 0; n < h.nodes.size(); ++n) B[n] = h.nodes[n].B;
  constexpr int block = 512;
  const int blocks = static_cast<int>((h.nodes.size() + block - 1) / block);
  parallel_for(blocks, threads, [&](int b) {
    const std::size_t end = std::min(h.nodes.size(), static_cast<std::size_t>(b + 1) * block);
    for (std::size_t n = static_cast<std::size_t>(b) * block; n < end; ++n) h.nodes[n].gathered = gather(h, h.nodes[n], B);
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

// exact_direct: every leaf's emission becomes its direct light D (the source term of
// the indirect system); a leaf keeps its D once computed (`known`, by node).
void set_direct_light(Hierarchy& h, const DirectLighting& lights, const FormFactorScene& blockers,
                      const DirectLightSettings& settings, std::vector<char>& known, int threads) {
  const std::vector<int> leaf = leaves(h);
  known.resize(h.nodes.size(), 0);
  parallel_for(static_cast<int>(leaf.size()), threads, [&](int k) {
    Node& node = h.nodes[leaf[k]];
    if (!known[leaf[k]]) node.E = open_direct_light(h, node, lights, blockers, settings.receiver_points);
  });
  for (int n : leaf) known[n] = 1;
  // BF-refinement's scale is the largest emission of the system solved: here D's.
  h.largest_emission = 0;
  for (int n : leaf) h.largest_emission = std::max(h.largest_emission, max_component(h.nodes[n].E));
}

}  // namespace

void check(const HierarchicalSettings& s) {
  check(s.refinement);
  if (!(s.tolerance > 0 && s.tolerance < 1)) throw std::invalid_argument("hierarchical radiosity: the tolerance must lie in (0, 1)");
  if (s.max_iterations < 1 || s.max_iterations > 1'000'000)
    throw std::invalid_argument("hierarchical radiosity: max iterations must lie in [1, 10^6]");
  if (s.max_rounds < 0 || s.max_rounds > 1000) throw std::invalid_argument("hierarchical radiosity: max rounds must lie in [0, 1000]");
  if (s.exact_direct) check(s.direct);
}

std::vector<Color> leaf_radiosity(const Hierarchy& h) { return radiosity_of(h, leaves(h)); }

SolverResult solve_links(Hierarchy& h, const SolverOptions& options, int threads) {
  const std::vector<int> leaf = leaves(h);
  if (options.reference && options.reference->size() != leaf.size())
    throw std::invalid_argument("hierarchical solve: the reference must hold one B per leaf");
  // The scales of the norms, as SolverMonitor's: E over the leaves, area-weighted.
  double e2 = 0, e_max = 0, power = 0;
  for (int n : leaf) {
    const Node& node = h.nodes[n];
    e2 += node.shape.area * length_squared(node.E);
    e_max = std::max(e_max, max_component(node.E));
    power += node.shape.area * mean(node.E);
  }
  e2 = e2 > 0 ? std::sqrt(e2) : 1, e_max = e_max > 0 ? e_max : 1, power = power > 0 ? power : 1;

  SolverResult result;
  result.method = "hierarchical";
  double seconds = 0, first = -1;
  for (int step = 1;; ++step) {
    const std::vector<Color> before = radiosity_of(h, leaf);
    const Timer timer;
    iterate(h, threads);
    seconds += timer.seconds();
    SolverStep row;
    row.step = step;
    row.seconds = seconds;
    double r2 = 0, r_max = 0, unshot = 0, d2 = 0, b2 = 0;
    bool finite = true;
    result.residual.resize(leaf.size());
    for (std::size_t k = 0; k < leaf.size(); ++k) {
      const Node& node = h.nodes[leaf[k]];
      const Color r = result.residual[k] = node.B - before[k];
      r2 += node.shape.area * length_squared(r);
      r_max = std::max(r_max, max_component(glm::abs(r)));
      unshot += node.shape.area * mean(glm::abs(r));
      finite = finite && is_finite(node.B);
      if (options.reference) {
        d2 += length_squared(node.B - (*options.reference)[k]);
        b2 += length_squared((*options.reference)[k]);
      }
    }
    row.residual_2 = std::sqrt(r2) / e2;
    row.residual_inf = r_max / e_max;
    row.unshot = unshot / power;
    if (options.reference) row.error = b2 > 0 ? std::sqrt(d2 / b2) : std::sqrt(d2);
    if (first < 0) first = row.residual_2;
    bool stop = true;
    if (!finite || !std::isfinite(row.residual_2) || row.residual_2 > 1e6 * std::max(first, 1e-12))
      result.status = SolveStatus::Diverged;
    else if (row.residual_2 <= options.tolerance)
      result.status = SolveStatus::Converged;
    else if (step >= options.max_steps)
      result.status = SolveStatus::StoppedAtLimit;
    else
      stop = false;
    if (stop || step % options.record_every == 0) {
      result.history.push_back(row);
      if (options.observer) options.observer(row, radiosity_of(h, leaf), result.residual);
    }
    if (stop) break;
  }
  result.B = radiosity_of(h, leaf);
  return result;
}

HierarchicalResult solve_hierarchical(Hierarchy& h, const FormFactorScene& blockers, const HierarchicalSettings& s,
                                      int threads) {
  check(s);
  HierarchicalResult result;
  SolverResult& all = result.solution;
  all.method = "hierarchical";
  SolverOptions options;
  options.tolerance = s.tolerance;
  options.max_steps = s.max_iterations;
  const Timer clock;
  bool settled = false;
  std::vector<char> known;  // exact_direct: the leaves whose D is set
  std::optional<DirectLighting> lights;
  if (s.exact_direct) {
    lights.emplace(make_mesh(h.surfaces, {1e300, 1}), s.direct.light_cells);
    for (Node& node : h.nodes) node.E = node.B = Color(0.0);  // B' before any light has bounced
  }
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
    const int before_this = all.history.empty() ? 0 : all.history.back().step;
    for (SolverStep step : solve.history) {  // numbered on, timed from the start
      step.step += before_this;
      step.seconds += start;
      all.history.push_back(step);
    }
    row.nodes = static_cast<int>(h.nodes.size());
    row.leaves = static_cast<int>(leaf.size());
    row.links = link_count(h);
    row.evaluated = count.evaluated;
    row.replaced = count.replaced;
    row.iterations = solve.history.back().step;
    row.change = relative_change(h, leaf, before);
    result.rounds.push_back(row);
    all.B = std::move(solve.B);
    all.residual = std::move(solve.residual);
    all.status = solve.status;
    if (solve.status == SolveStatus::Diverged) return result;
  }
  if (all.status == SolveStatus::Converged && !settled) all.status = SolveStatus::StoppedAtLimit;
  if (s.exact_direct) {
    const std::vector<int> leaf = leaves(h);
    for (std::size_t k = 0; k < leaf.size(); ++k) {
      result.direct.push_back(h.nodes[leaf[k]].E);
      all.B[k] += h.surfaces[h.nodes[leaf[k]].surface].emission;  // B = E + B'
    }
  }
  return result;
}

}  // namespace gi
