#pragma once
#include <string>

#include "gi/radiosity/hierarchical/link.hpp"

namespace gi {

// What the oracle says about a link: it is accurate enough, or which end to cut into
// four (RenderPark's "famous oracle function").
enum class Refinement { Accept, SplitReceiver, SplitSource };
std::string name(Refinement refinement);  // "accept", "split receiver", "split source"

// The light a link carries per unit of F, as a range over its source: rho_p B_q at the
// source's darkest and brightest part (its children; the source itself at a leaf),
// over the scene's largest emission. F-refinement, before any B is known: 1 and 1.
struct Brightness {
  double least = 1, greatest = 1;
};

// The oracle for the link that brings q's light to p. A link hands the receiver one
// number, rho_p F_pq V B_q, for all of it; at a point x of the receiver the light is
// rho_p F(x -> q) V(x) B(y) over the source's points y. So the error at the worst point
// is bounded by the spread of the transfer (Lischinski, Tampieri and Greenberg 1994;
// Holzschuch and Sillion 1998 bound the same spread):
//   error = greatest * F_max - least * F_min
// with F_min and F_max the least and greatest point-to-polygon F over the receiver's
// sample points (Link). A link its shadow rays found partly hidden has a shadow's edge
// inside it, where the light falls to nothing: there F_min counts as 0. A link they
// found wholly hidden is judged as a visible one (a refinement that stopped wherever
// its few rays happened to miss the light would lose, on average, the light they missed).
//
// Hanrahan, Salzman and Aupperle's oracle (1991) bounded F itself, brightness *
// max(F_pq, F_qp): a link that carries much light but the same to every point of its
// receiver (F constant) is cut anyway, and one whose F changes several-fold across a
// receiver beside its source is not, if F is small (measured in docs/13: corner
// leaves up to 26% wrong).
//
// When the error exceeds the threshold, the oracle splits the end the error lives in:
//   error = greatest (F_max - F_min)  +  (greatest - least) F_min
//           F changing across the        B changing across the source:
//           receiver: split the receiver split the source
// (the larger part decides). F is exact for the whole source (the point-to-polygon
// formula), so cutting the source never makes the receiver's F any better: it only
// shares the spread among four links that all still reach the same receiver, each
// below the threshold, their errors adding up again at every leaf below it. Hanrahan
// et al. split the end that looks bigger (F_pq >= F_qp: the source); with that rule
// a closed white furnace came out 13% bright in a corner at minimum area 1e-4 (docs/13).
// A shadow edge inside (0 < V < 1) can be moved by cutting either end: there the
// bigger end is cut. An end at the minimum area cannot be split; then the other end
// is, and when neither can, the link is accepted as it is.
Refinement oracle(const Link& link, Brightness brightness, double threshold, bool receiver_can_split,
                  bool source_can_split);

}  // namespace gi
