#pragma once
#include <vector>

#include "gi/radiosity/form_factors/form_factors.hpp"
#include "gi/radiosity/hierarchical/hierarchy.hpp"

namespace gi {

// Conservation. Seen from the leaves, the links are a matrix T: leaf p gathers
//   sum_q T_pq B_q,   T_pq = F_l V_l a_q / a_Q
// over the links l of p and of its ancestors P, q a leaf of the link's source Q (of
// the quarter of Q the link reads, by its share V_c, where Q has children; a the open
// areas): push hands P's light to all of it, pull sends Q's mean. Two sums of T are
// facts of the scene, not of the mesh:
//   its row     sum_q T_pq       the share of p's view that the surfaces fill
//   its column  sum_p a_p T_pq   a_q times the share of q's light that lands on a surface
// and for a leaf that sees only surfaces (every point of a closed room) both are 1.
// Then, for a uniform rho, the radiosity keeps the power exactly: sum a B = sum a E +
// rho sum a B, so sum a B = sum a E / (1 - rho). But a link's F is the mean over its
// receiver, so a leaf below the receiver inherits the mean of a larger piece (its row
// is off), and a source sends one mean B by one F (its leaves' columns are off): in a
// closed white box 0.11% at a corner leaf at minimum area 3e-4 (4.9% deep below its
// links), and with the Cornell box's blocks in it 6-36% at single leaves (docs/13).
//
// The cure keeps the links and scales each such leaf twice, T'_pq = r_p T_pq c_q, r its
// gather_scale and c its send_scale (Sinkhorn and Knopp's balancing of a matrix), until
// every row and every column is 1. The scales stay near 1 (0.79-1.23 for 98% of the
// closed Cornell box's leaves): the links are good, only their sums are made exact.
//
// Whether a leaf's row is 1 is a fact of its own view, not of the room: in an open
// room a leaf that sees only surfaces (a ceiling round a skylight, looking down) has
// row and column 1 as in a closed one, and is balanced. A leaf that sees out of the
// scene, or the back of a surface (which reflects nothing), has a view below 1 by the
// share that escapes, which only the links estimate; its sums are left as the links
// have them (scales 1): balanced to 1 it would keep light that leaves. Holding them to
// an estimate could ask the impossible (two surfaces whose estimates of the light
// between them disagree) and moves light from one link of a leaf to another:
// measured, it made a shadowed square 12% off where the links alone were 5%.

// Does every probe ray from the leaf meet the front of a surface? 256 directions, one
// in each of 256 cells that carry an equal share of the cosine-weighted view, cast 64
// from the centre of an open cell (exposure.hpp) in each quarter of the leaf. An
// opening that slips between them (about a cell's share, 1/256, or more where the
// quarters see it differently: 0.94% for a wall leaf by the ceiling of the skylight
// box) is missed: its share of the view is then counted as seen. False for a leaf with
// no open cell.
bool sees_only_surfaces(const FormFactorScene& blockers, const Hierarchy& hierarchy, int leaf);

// The balance reached over the leaves that see only surfaces: the largest relative
// error of a row or column sum, before and after.
struct Balance {
  int leaves = 0;
  int enclosed = 0;        // leaves that see only surfaces: the ones balanced
  int sweeps = 0;          // each a row and a column scaling
  double before = 0, after = 0;
  bool converged = false;  // after <= tolerance; if not, every scale is left at 1
};

// Sets every leaf's gather_scale and send_scale: for a leaf that sees only surfaces
// (sees_only_surfaces, against `blockers`, the input surfaces) so that its row and
// column are 1, by rows and columns scaled in turn until the largest error is below
// `tolerance`; for any other leaf 1. Gives up after max_sweeps, leaving every scale 1.
// Same scales for any thread count.
Balance balance_links(Hierarchy& hierarchy, const FormFactorScene& blockers, int threads, double tolerance = 1e-12,
                      int max_sweeps = 100);

// Every scale back to 1: the links as they are (refinement changes them; balance again after it).
void unbalance(Hierarchy& hierarchy);

}  // namespace gi
