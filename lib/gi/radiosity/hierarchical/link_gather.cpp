#include "gi/radiosity/hierarchical/link_gather.hpp"

#include <array>
#include <cmath>
#include <functional>

#include "gi/core/not_implemented.hpp"
#include "gi/core/parallel.hpp"
#include "gi/radiosity/form_factors/form_factor_formulas.hpp"
#include "gi/radiosity/hierarchical/exposure.hpp"

namespace gi {

// light_l: what the link hands its receiver, before rho (as push_pull.cpp's gather).
Color link_light(const Hierarchy& h, const Link& link) {
  const Node& q = h.nodes[link.source];
  if (q.leaf()) return link.F * link.visibility * q.B;
  Color sum(0.0);
  for (int c = 0; c < 4; ++c) sum += link.F * link.by_quarter[c] * h.nodes[q.children[c]].B;
  return sum;
}

namespace {

// Some of the link's shadow rays got through and some did not.
bool shadow_edge_inside(const Link& link) { return link.visibility > 0 && link.visibility < 1; }

}  // namespace

LinkGather::LinkGather(const Hierarchy& h)
    : hierarchy_(&h), blockers_(surface_shapes(h)), far_(h.nodes.size(), Color(0.0)), near_(h.nodes.size()),
      shafts_(h.nodes.size()) {
  for (std::size_t n = 0; n < h.nodes.size(); ++n) {
    shafts_[n].resize(h.nodes[n].links.size());
    for (std::size_t k = 0; k < h.nodes[n].links.size(); ++k) {
      const Link& link = h.nodes[n].links[k];
      if (!(link.F > 0 && (link.F_max > near_spread * link.F_min || shadow_edge_inside(link)))) {
        far_[n] += link_light(h, link);
        continue;
      }
      near_[n].push_back(static_cast<int>(k));
      if (!shadow_edge_inside(link)) continue;
      // Every ray light_at casts for this link runs between the two nodes' lifted outlines.
      std::vector<vec3> corners;
      for (const int node : {link.receiver, link.source})
        for (const auto& [u, v] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}})
          corners.push_back(lifted_point(h, h.nodes[node], u, v));
      shafts_[n][k].emplace(blockers_, corners);
    }
  }
}

Color LinkGather::light_at(const Link& link, int leaf, const vec3& x) const {
  const Hierarchy& h = *hierarchy_;
  if (!shadow_edge_inside(link)) return link_light(h, link);
  const Node& p = h.nodes[leaf];
  const Node& q = h.nodes[link.source];
  const vec3 from = lifted(h, p.surface, x);  // where the links' own shadow rays start
  if (p.open != 0xFFFF && buried(blockers_, from, p.shape.normal, std::sqrt(h.total_area))) return link_light(h, link);
  // The link's shaft, found by the link's place among its receiver's links (a link
  // made by hand, outside the hierarchy, has none: the whole scene is tested).
  const std::vector<Link>& links = h.nodes[link.receiver].links;
  const Link* first = links.data();
  const Shaft* shaft = nullptr;
  if (std::less_equal<const Link*>()(first, &link) && std::less<const Link*>()(&link, first + links.size()))
    if (const std::optional<Shaft>& s = shafts_[static_cast<std::size_t>(link.receiver)][&link - first]) shaft = &*s;
  constexpr int n = gather_rays_per_side;
  Color through(0.0);
  double carrying = 0;
  for (int k = 0; k < n * n; ++k) {
    const double s = (k % n + 0.5) / n, t = (k / n + 0.5) / n;
    const vec3 to = lifted_point(h, q, s, t);
    const vec3 d = to - from;
    const double cos_p = dot(d, p.shape.normal), cos_q = -dot(d, q.shape.normal);  // times |d| each
    if (cos_p <= 0 || cos_q <= 0) continue;                                        // carries no light
    const double w = cos_p * cos_q / (dot(d, d) * dot(d, d));
    carrying += w;
    if (!(shaft ? shaft->visible(from, to) : blockers_.visible(from, to))) continue;
    through += w * (q.leaf() ? q.B : h.nodes[q.children[(s >= 0.5) + 2 * (t >= 0.5)]].B);  // its quarter's B
  }
  return carrying > 0 ? link.F * through / carrying : link_light(h, link);
}

Color LinkGather::at(int leaf, const vec3& x) const {
  // BEGIN EXERCISE 13.5 gathering at a point
  // The leaf's links and every ancestor's: push-pull hands what a node gathered to all
  // of it. A far link counts as it is (far_), a near one as x sees it (light_at)
  // scaled by F(x -> q) / F_l, with the receiver's normal at x.
  const Hierarchy& h = *hierarchy_;
  const vec3& n = h.nodes[leaf].shape.normal;
  Color sum(0.0);
  for (int a = leaf; a >= 0; a = h.nodes[a].parent) {
    sum += far_[a];
    for (int k : near_[a]) {
      const Link& link = h.nodes[a].links[k];
      sum += light_at(link, leaf, x) * (point_to_polygon_unchecked(x, n, h.nodes[link.source].shape) / link.F);
    }
  }
  return h.nodes[leaf].rho * sum;
  // END EXERCISE 13.5
}

std::vector<Color> gathered_at_vertices(const Hierarchy& h, const LeafMesh& leaves, int threads) {
  const LinkGather gather(h);
  const std::vector<Element>& elements = leaves.mesh.elements;
  std::vector<char> t_vertex(leaves.mesh.vertices.size(), 0);
  for (const LeafMesh::TVertex& tv : leaves.t_vertices) t_vertex[tv.vertex] = 1;
  // Corners in the order of Polygon::corners: (0, 0), (1, 0), (1, 1), (0, 1) of the leaf's square.
  constexpr double lo = gather_inset, hi = 1 - gather_inset;
  constexpr std::array<vec2, 4> corner{vec2(lo, lo), vec2(hi, lo), vec2(hi, hi), vec2(lo, hi)};
  std::vector<std::array<Color, 4>> at(elements.size());
  parallel_for(static_cast<int>(elements.size()), threads, [&](int e) {
    const int leaf = leaves.node[e];
    for (int k = 0; k < 4; ++k)
      if (!t_vertex[elements[e].vertices[k]])
        at[e][k] = gather.at(leaf, node_point(h, h.nodes[leaf], corner[k].x, corner[k].y));
  });
  std::vector<Color> sum(leaves.mesh.vertices.size(), Color(0.0));
  std::vector<double> weight(sum.size(), 0.0);
  for (std::size_t e = 0; e < elements.size(); ++e)
    for (int k = 0; k < 4; ++k) {
      sum[elements[e].vertices[k]] += elements[e].shape.area * at[e][k];
      weight[elements[e].vertices[k]] += elements[e].shape.area;
    }
  for (std::size_t v = 0; v < sum.size(); ++v)
    if (weight[v] > 0) sum[v] /= weight[v];
  settle_t_vertices(leaves, sum);
  return sum;
}

}  // namespace gi
