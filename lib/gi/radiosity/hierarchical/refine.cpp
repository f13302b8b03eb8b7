#include "gi/radiosity/hierarchical/refine.hpp"

#include <stdexcept>
#include <string>

#include "gi/core/parallel.hpp"
#include "gi/radiosity/hierarchical/exposure.hpp"
#include "gi/radiosity/hierarchical/link_estimate.hpp"

namespace gi {

namespace {

struct Pair {
  int receiver, source;
};

struct Verdict {
  Link link;
  Refinement what = Refinement::Accept;
  bool exchange = false;  // can_exchange
};

// The oracle's brightness: 1 for F-refinement; for BF-refinement the light the link
// would carry per unit F, rho_p B_q, over the scene's largest emission, so that the
// threshold is a fraction of the light source's radiosity whatever the units. Its
// range over the source is read from the source's children, where it has any: the
// mean B_q a link carries is right for every point of the receiver only if B is
// constant over the source.
Brightness brightness(const Hierarchy& h, const Node& p, const Node& q, Criterion criterion) {
  if (criterion == Criterion::FormFactor) return {1, 1};
  if (h.largest_emission <= 0) return {0, 0};
  const auto relative = [&](const Node& part) { return max_component(p.rho * part.B) / h.largest_emission; };
  if (q.leaf()) return {relative(q), relative(q)};
  Brightness b{1e300, 0};
  for (int child : q.children) {
    const double r = relative(h.nodes[child]);
    b.least = std::min(b.least, r), b.greatest = std::max(b.greatest, r);
  }
  return b;
}

double threshold(const RefinementSettings& s, Criterion criterion) {
  return criterion == Criterion::FormFactor ? s.form_factor_threshold : s.threshold;
}

Verdict judge(const Hierarchy& h, const FormFactorScene& blockers, Pair pair, const RefinementSettings& s,
              Criterion criterion) {
  const Node& p = h.nodes[pair.receiver];
  const Node& q = h.nodes[pair.source];
  Verdict v;
  if (!(v.exchange = can_exchange(p.shape, q.shape))) return v;
  v.link = estimate_form_factors(h, pair.receiver, pair.source, s.order);
  const bool split_p = can_split(h, p, s), split_q = can_split(h, q, s);
  const Brightness b = brightness(h, p, q, criterion);
  if (v.link.F > 0) {
    // V counts in the oracle only as whether a shadow edge lies inside (0 < V < 1).
    // Where it would cut the same end either way the link is not kept: no rays needed.
    Link clear = v.link, edge = v.link;
    clear.visibility = 1, edge.visibility = 0.5;
    const Refinement what = oracle(clear, b, threshold(s, criterion), split_p, split_q);
    if (what != Refinement::Accept && what == oracle(edge, b, threshold(s, criterion), split_p, split_q)) {
      v.what = what;
      return v;
    }
  }
  estimate_visibility(v.link, blockers, h, s.rays_per_side, s.seed);
  if (v.link.F == 0 && v.link.F_back == 0 && v.link.visibility > 0) {
    // Facing, yet neither's sample points see the other: the estimates say nothing
    // (each lies partly behind the other's plane). Cut the larger until they do.
    v.what = split_p && (p.shape.area >= q.shape.area || !split_q) ? Refinement::SplitReceiver
             : split_q                                              ? Refinement::SplitSource
                                                                    : Refinement::Accept;
    return v;
  }
  v.what = oracle(v.link, b, threshold(s, criterion), split_p, split_q);
  return v;
}

// Judges the candidates wave by wave until every one is stored or gone.
void refine_pairs(Hierarchy& h, const FormFactorScene& blockers, std::vector<Pair> wave, const RefinementSettings& s,
                  Criterion criterion, int threads, RefinementCount& count) {
  constexpr int block = 256;
  while (!wave.empty()) {
    measure_exposure(h, blockers, h.exposed, threads);  // the nodes the last wave made
    h.exposed = static_cast<int>(h.nodes.size());
    std::vector<Verdict> verdicts(wave.size());
    const int blocks = static_cast<int>((wave.size() + block - 1) / block);
    parallel_for(blocks, threads, [&](int b) {
      const std::size_t end = std::min(wave.size(), static_cast<std::size_t>(b + 1) * block);
      for (std::size_t k = static_cast<std::size_t>(b) * block; k < end; ++k)
        verdicts[k] = judge(h, blockers, wave[k], s, criterion);
    });
    std::vector<Pair> next;
    for (std::size_t k = 0; k < wave.size(); ++k) {
      const Verdict& v = verdicts[k];
      const auto [p, q] = wave[k];
      ++count.evaluated;
      if (!v.exchange) {
        ++count.carry_nothing;
        continue;
      }
      switch (v.what) {
        case Refinement::Accept:
          // A link whose few shadow rays all found it hidden is kept (it carries
          // nothing now): BF-refinement judges only stored links, and one of them may
          // yet show a gap the rays missed. Dropped, F-refinement's coarse threshold
          // lost for good a view a face's foot had of the floor (docs/13).
          ++count.accepted;
          if (v.link.F > 0 && h.nodes[p].open && h.nodes[q].open)
            h.nodes[p].links.push_back(v.link);
          else
            ++count.carry_nothing;
          break;
        case Refinement::SplitReceiver:
          ++count.split_receiver;
          if (h.nodes[p].leaf()) split(h, p);
          for (int child : h.nodes[p].children) next.push_back({child, q});
          break;
        case Refinement::SplitSource:
          ++count.split_source;
          if (h.nodes[q].leaf()) split(h, q);
          for (int child : h.nodes[q].children) next.push_back({p, child});
          break;
      }
    }
    wave = std::move(next);
  }
}

}  // namespace

void check(const RefinementSettings& s) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("hierarchical radiosity: " + what); };
  if (!(s.form_factor_threshold > 0 && s.form_factor_threshold <= 10)) fail("the F threshold must lie in (0, 10]");
  if (!(s.threshold > 0 && s.threshold <= 10)) fail("the BF threshold must lie in (0, 10]");
  if (!(s.min_area >= 1e-12 && s.min_area <= 1)) fail("the minimum area must lie in [1e-12, 1] (of the scene's)");
  if (s.order < 2 || s.order > 4) fail("the quadrature order must lie in [2, 4] (one point sees no spread)");
  if (s.rays_per_side < 1 || s.rays_per_side > 16) fail("the shadow rays per side must lie in [1, 16]");
}

bool can_split(const Hierarchy& h, const Node& node, const RefinementSettings& s) {
  return node.level < 24 && node.shape.area >= 4 * s.min_area * h.total_area;
}

RefinementCount link_surfaces(Hierarchy& h, const FormFactorScene& blockers, const RefinementSettings& s, int threads) {
  check(s);
  std::vector<Pair> roots;
  const int n = static_cast<int>(h.surfaces.size());
  for (int p = 0; p < n; ++p)
    for (int q = 0; q < n; ++q)
      if (p != q) roots.push_back({p, q});
  RefinementCount count;
  refine_pairs(h, blockers, std::move(roots), s, Criterion::FormFactor, threads, count);
  return count;
}

RefinementCount refine_links(Hierarchy& h, const FormFactorScene& blockers, const RefinementSettings& s, int threads) {
  check(s);
  RefinementCount count;
  std::vector<Pair> wave;
  const int nodes = static_cast<int>(h.nodes.size());  // splits below append; new nodes have no links yet
  for (int n = 0; n < nodes; ++n) {
    // Taken out of the node while splits below may move the nodes.
    const std::vector<Link> links = std::move(h.nodes[n].links);
    std::vector<Link> kept;
    kept.reserve(links.size());
    for (const Link& link : links) {
      const Node& p = h.nodes[link.receiver];
      const Node& q = h.nodes[link.source];
      const Refinement what = oracle(link, brightness(h, p, q, Criterion::Brightness), s.threshold,
                                     can_split(h, p, s), can_split(h, q, s));
      if (what == Refinement::Accept) {
        kept.push_back(link);
        continue;
      }
      ++count.replaced;
      const int end = what == Refinement::SplitReceiver ? link.receiver : link.source;
      if (h.nodes[end].leaf()) split(h, end);
      for (int child : h.nodes[end].children)
        wave.push_back(what == Refinement::SplitReceiver ? Pair{child, link.source} : Pair{link.receiver, child});
    }
    h.nodes[n].links = std::move(kept);
  }
  refine_pairs(h, blockers, std::move(wave), s, Criterion::Brightness, threads, count);
  return count;
}

}  // namespace gi
