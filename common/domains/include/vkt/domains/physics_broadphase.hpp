#pragma once
// The broad phase of chapter 14: which pairs of boxes may touch. Each box is
// wrapped in its world-space axis-aligned bounding box (AABB); two boxes can
// only touch where their AABBs overlap. Two ways to find those pairs: every
// pair (n^2, the reference) and sort-and-sweep along x. Both return the same
// pairs in the same order, so the simulation is the same bit for bit
// whichever found them.
//
// Plain C++ and glm: no Vulkan here.

#include "vkt/domains/physics_body.hpp"

#include <compare>
#include <cstdint>
#include <span>
#include <vector>

namespace vkt::physics {

struct Aabb {
    glm::vec3 low{0.0f}, high{0.0f};
};

// [world-aabb]
// The AABB of a turned box: along world axis k it reaches as far as the sum of
// its three half axes projected on k, |R_k0| h_0 + |R_k1| h_1 + |R_k2| h_2,
// grown by `margin` on every side (contacts are made slightly before touching).
Aabb world_aabb(glm::vec3 centre, const glm::mat3& rotation, glm::vec3 half_extents, float margin);
// [/world-aabb]

// Overlapping by more than zero on all three axes: AABBs that only touch do not.
inline bool overlaps(const Aabb& a, const Aabb& b) {
    return a.low.x < b.high.x && b.low.x < a.high.x && a.low.y < b.high.y && b.low.y < a.high.y &&
           a.low.z < b.high.z && b.low.z < a.high.z;
}

// A pair of bodies that may touch: a < b. At least one of them moves: it is
// neither static nor asleep. (Two static bodies never need a contact, and a
// sleeper's contacts with static or sleeping bodies are kept as they were
// when it fell asleep: nothing there has moved since.)
struct Pair {
    uint32_t a = 0, b = 0;
    auto operator<=>(const Pair&) const = default;
};

// Every overlapping pair, sorted by (a, b): n(n - 1) / 2 tests. The reference.
// aabbs[i] belongs to bodies[i].
void find_pairs_brute_force(std::span<const Aabb> aabbs, std::span<const Body> bodies,
                            std::vector<Pair>& pairs);

// The same pairs, sorted the same way, by sort-and-sweep: sort the boxes by
// their lowest x, walk them in that order, and test each box only against the
// boxes that start before it ends along x. The order is kept from step to
// step: last step's order is nearly sorted already, which insertion sort
// finishes in about n steps.
class SweepAndPrune {
public:
    void find_pairs(std::span<const Aabb> aabbs, std::span<const Body> bodies,
                    std::vector<Pair>& pairs);

private:
    std::vector<uint32_t> order_;
    // The boxes in sorted order, side by side in memory for the sweep.
    struct Entry {
        Aabb box;
        uint32_t index;
        uint32_t moves;
    };
    std::vector<Entry> sorted_;
    std::vector<uint32_t> counts_;
    std::vector<Pair> unsorted_;
};

}  // namespace vkt::physics
