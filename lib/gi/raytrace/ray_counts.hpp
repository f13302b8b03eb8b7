#pragma once
#include <array>
#include <cstdint>

namespace gi {

// The lecture's four kinds of ray.
enum class RayKind { Primary, Shadow, Reflected, Transmitted };
inline constexpr int ray_kind_count = 4;
inline constexpr const char* ray_kind_names[ray_kind_count] = {"primary", "shadow", "reflected", "transmitted"};

// How many rays of each kind were cast at each depth (depth 0 = the eye ray and the
// shadow rays from its hit). Each thread counts into its own RayCounts (PerThread) and
// the counts are added afterwards, so the totals do not depend on the thread count.
// Aligned to a cache line: neighbouring threads' counts sit side by side in memory, and
// two threads incrementing counters in one line would keep stealing it from each
// other (false sharing) -- when a busy counter sat at the end of this struct, that
// alone cost a quarter of the second core (docs/05_acceleration.md).
struct alignas(64) RayCounts {
  static constexpr int max_depth = 64;
  std::array<std::array<std::uint64_t, max_depth + 1>, ray_kind_count> at{};

  void count(RayKind kind, int depth) { ++at[static_cast<int>(kind)][depth]; }

  std::uint64_t of(RayKind kind) const {
    std::uint64_t sum = 0;
    for (std::uint64_t n : at[static_cast<int>(kind)]) sum += n;
    return sum;
  }
  std::uint64_t at_depth(int depth) const {
    std::uint64_t sum = 0;
    for (const auto& kind : at) sum += kind[depth];
    return sum;
  }
  std::uint64_t total() const {
    std::uint64_t sum = 0;
    for (int k = 0; k < ray_kind_count; ++k) sum += of(static_cast<RayKind>(k));
    return sum;
  }
  RayCounts& operator+=(const RayCounts& other) {
    for (int k = 0; k < ray_kind_count; ++k)
      for (int d = 0; d <= max_depth; ++d) at[k][d] += other.at[k][d];
    return *this;
  }
};

}  // namespace gi
