#include "gi/radiosity/hierarchical/oracle.hpp"

#include <algorithm>

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

Refinement oracle(const Link& link, double brightness, double threshold, bool receiver_can_split,
                  bool source_can_split) {
  // BEGIN EXERCISE 13.1 the refinement oracle
  double error = brightness * std::max(link.F, link.F_back);
  if (link.visibility > 0 && link.visibility < 1) error *= partial_visibility_factor;  // a shadow edge inside
  if (error <= threshold) return Refinement::Accept;
  if (link.F >= link.F_back) return source_can_split ? Refinement::SplitSource : Refinement::Accept;
  return receiver_can_split ? Refinement::SplitReceiver : Refinement::Accept;
  // END EXERCISE 13.1
}

}  // namespace gi
