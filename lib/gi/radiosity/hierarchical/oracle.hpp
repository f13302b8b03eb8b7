#pragma once
#include <string>

#include "gi/radiosity/hierarchical/link.hpp"

namespace gi {

// What the oracle says about a link: it is accurate enough, or which end to cut into
// four (RenderPark's "famous oracle function").
enum class Refinement { Accept, SplitReceiver, SplitSource };
std::string name(Refinement refinement);  // "accept", "split receiver", "split source"

// Hanrahan, Salzman and Aupperle's oracle for the link that brings q's light to p.
// Its error estimate is the larger of the two form factors, times a brightness:
//   error = brightness * max(F_pq, F_qp)
// F-refinement (before any B is known): brightness 1, so every form factor is
// computed to the threshold. BF-refinement: brightness = rho_p B_q / E_max (the
// largest channel), so a link is refined as much as the light it carries matters.
// Visibility does not lower the error: a link its shadow rays found wholly hidden is
// cut as finely as a visible one would be (a refinement that stopped wherever its
// rays happened to miss the light would lose, on average, the light they missed). A
// link they found partly hidden has a shadow's edge inside it, where the light jumps
// from all to nothing across the receiver: its error counts partial_visibility_factor
// times, so shadows are drawn finer than the light around them.
//
// When the error exceeds the threshold, the oracle splits the end that looks bigger
// from the other: F_pq >= F_qp means the source fills more of the receiver's view than
// the receiver of the source's (A_q >= A_p, by reciprocity), so the source is split.
// An end below the minimum area cannot be split; then the link is accepted as it is.
inline constexpr double partial_visibility_factor = 4;
Refinement oracle(const Link& link, double brightness, double threshold, bool receiver_can_split,
                  bool source_can_split);

}  // namespace gi
