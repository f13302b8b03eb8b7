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
  // error = greatest (F_max - F_min) + (greatest - least) F_min: F changing across the
  // receiver, which only cutting the receiver shrinks, and B changing across the
  // source, which only cutting the source does. A shadow edge: the end that looks bigger.
  const double over_receiver = brightness.greatest * (link.F_max - F_min);
  const double over_source = (brightness.greatest - brightness.least) * F_min;
  const bool cut_source = shadow_edge_inside ? link.F >= link.F_back : over_source > over_receiver;
  if (cut_source && source_can_split) return Refinement::SplitSource;
  if (receiver_can_split) return Refinement::SplitReceiver;
  if (source_can_split) return Refinement::SplitSource;
  return Refinement::Accept;
  // END EXERCISE 13.1
}

}  // namespace gi
