#pragma once
#include <cstdint>

namespace gi {

// What ray queries cost, for the lesson's tables: tree nodes visited, ray-box tests
// (slab tests) and ray-primitive tests. Sum them over many rays with +=.
struct TraversalCounts {
  std::uint64_t nodes_visited = 0;
  std::uint64_t box_tests = 0;
  std::uint64_t primitive_tests = 0;

  TraversalCounts& operator+=(const TraversalCounts& other) {
    nodes_visited += other.nodes_visited;
    box_tests += other.box_tests;
    primitive_tests += other.primitive_tests;
    return *this;
  }
};

}  // namespace gi
