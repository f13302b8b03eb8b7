#include "gi/radiosity/hierarchical/oracle.hpp"

#include "gi/core/not_implemented.hpp"

namespace gi {

std::string name(Refinement refinement) {
  switch (refinement) {
    case Refinement::Accept: return "accept";
    case Refinement::SplitReceiver: return "split receiver";
    case Refinement::SplitSource: return "split source";
  }
  return "?";
}

Refinement oracle(const Link& link, Brightness brightness, double threshold, bool receiver_can_split,
                  bool source_can_split) {
  // BEGIN EXERCISE 13.1 the refinement oracle
  const bool shadow_edge_inside = link.visibility > 0 && link.visibility < 1;
  const double F_min = shadow_edge_inside ? 0.0 : link.F_min;
  const double error = brightness.greatest * link.F_max - brightness.least * F_min;
  if (error <= threshold) return Refinement::Accept;
  const bool source_bigger = link.F >= link.F_back;
  if (source_bigger && source_can_split) return Refinement::SplitSource;
  if (receiver_can_split) return Refinement::SplitReceiver;
  if (source_can_split) return Refinement::SplitSource;
  return Refinement::Accept;
  // END EXERCISE 13.1
}

}  // namespace gi
