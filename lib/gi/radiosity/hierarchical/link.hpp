#pragma once
#include <array>

namespace gi {

// A link carries light from one node of the hierarchy (its source q) to another
// (its receiver p), at the level the refinement oracle accepted (oracle.hpp). The
// receiver gathers over its links:
//   gathered_p = rho_p * sum over links of F_pq * V_pq * B_q
// As in Hanrahan, Salzman and Aupperle's algorithm, and RenderPark's Interaction, a
// link is a record stored with its receiver (Node::links).
struct Link {
  int receiver = -1, source = -1;  // node indices
  double F = 0;           // F_pq, receiver to source, with nothing in between (analytic, link_estimate.hpp)
  double F_back = 0;      // F_qp, source to receiver: the oracle's second estimate
  double visibility = 0;  // V_pq in [0, 1]: the share of the light between them that gets through (visibility.hpp)
  // The least and the greatest point-to-polygon F from the receiver's sample points to
  // the source, nothing in between: how much F changes across the receiver, which a
  // link (one F for the whole receiver) cannot carry. The oracle's error estimate.
  // Floats: estimates, and a link stays at 56 bytes.
  float F_min = 0, F_max = 0;
  // V split by where the light lands: the share that gets through into each quarter
  // of the source (its children's order; they add up to V). A source that is not a leaf
  // sends each quarter's light by that quarter's own B (push_pull.hpp's gather).
  std::array<float, 4> by_quarter{};
};

}  // namespace gi
