#pragma once
#include <cstddef>
#include <cstdint>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/hierarchical/hierarchy.hpp"
#include "gi/radiosity/hierarchical/oracle.hpp"

namespace gi {

// How finely hierarchical radiosity links and cuts the scene.
struct RefinementSettings {
  double form_factor_threshold = 0.1;  // F_eps of F-refinement (the first round): F_max - F_min above it is split
  double threshold = 1e-3;  // BF_eps of BF-refinement: the spread of rho_p B_q F above it x E_max is split
  double min_area = 1e-4;   // no node smaller than 4x this fraction of the scene's area is split
  // F of a link: the mean of the exact point-to-polygon F at order x order Gauss points
  // of the receiver, and its spread over them (the oracle's error), so at least 2: the
  // centre alone (Hanrahan et al.'s) sees no spread, and F from a point is far
  // from its mean over a large receiver beside its source (the Cornell box's blocks
  // came out 10-27% too dark against a uniform solution). Order 3 against 2 (2.25x
  // the F evaluations): 1.60% against 1.90% from the truth at BF_eps 3e-4, direct
  // per pixel (docs/13).
  int order = 3;
  int rays_per_side = 4;    // visibility: n x n shadow rays per link
  std::uint64_t seed = 1;   // of the shadow rays' jitter (visibility.hpp)
};
// Throws std::invalid_argument, naming the setting and its range: thresholds in
// (0, 10], min_area in [1e-12, 1], order in [2, 4], rays_per_side in [1, 16].
void check(const RefinementSettings& settings);

// F-refinement before any radiosity is known, BF-refinement against the current B.
enum class Criterion { FormFactor, Brightness };

// What a refinement did: candidate links looked at (each an F, F_back and V), the
// oracle's answers, links between nodes that cannot exchange light (can_exchange)
// or carry none (wholly hidden, or F = 0), and links of an earlier round replaced.
struct RefinementCount {
  std::size_t evaluated = 0, accepted = 0, split_receiver = 0, split_source = 0, carry_nothing = 0, replaced = 0;
};

// Can this node be cut into four? Not when its children would be smaller than the
// minimum area (or it is 24 levels deep).
bool can_split(const Hierarchy& hierarchy, const Node& node, const RefinementSettings& settings);

// Links every pair of surfaces that can exchange light, refined with F-refinement:
// starting from the roots, each candidate link is judged by the oracle and either
// stored with its receiver or replaced by the four links of the split end's children.
// Candidates are judged in waves, in parallel (each judgement reads the hierarchy
// only), and the verdicts applied in order: the same hierarchy for any thread count.
RefinementCount link_surfaces(Hierarchy& hierarchy, const FormFactorScene& blockers, const RefinementSettings& settings,
                              int threads);

// BF-refinement: every link the oracle no longer accepts against the current B is
// replaced, as above. Returns what changed; nothing replaced means the hierarchy has
// settled for this B.
RefinementCount refine_links(Hierarchy& hierarchy, const FormFactorScene& blockers, const RefinementSettings& settings,
                             int threads);

}  // namespace gi
