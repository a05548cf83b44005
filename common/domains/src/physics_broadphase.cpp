#include "vkt/domains/physics_broadphase.hpp"

#include <algorithm>
#include <cmath>

namespace vkt::physics {

// [world-aabb-code]
Aabb world_aabb(glm::vec3 centre, const glm::mat3& r, glm::vec3 h, float margin) {
    // glm is column-major: r[j] is the body's axis j in world space, r[j][k]
    // its world component k.
    glm::vec3 reach(margin);
    for (int j = 0; j < 3; ++j) reach += glm::abs(r[j]) * h[j];
    return {centre - reach, centre + reach};
}
// [/world-aabb-code]

namespace {
bool either_moves(const Body& a, const Body& b) {
    return a.is_active() || b.is_active();
}
}  // namespace

void find_pairs_brute_force(std::span<const Aabb> aabbs, std::span<const Body> bodies,
                            std::vector<Pair>& pairs) {
    pairs.clear();
    const auto n = uint32_t(aabbs.size());
    for (uint32_t i = 0; i < n; ++i)
        for (uint32_t j = i + 1; j < n; ++j)
            if (either_moves(bodies[i], bodies[j]) && overlaps(aabbs[i], aabbs[j]))
                pairs.push_back({i, j});
    // Already sorted by (a, b).
}

// [sweep]
void SweepAndPrune::find_pairs(std::span<const Aabb> aabbs, std::span<const Body> bodies,
                               std::vector<Pair>& pairs) {
    const auto n = uint32_t(aabbs.size());
    // Sort by the lowest x, ties by index, so the order never depends on the
    // sorting algorithm's whims.
    auto before = [&](uint32_t i, uint32_t j) {
        const float xi = aabbs[i].low.x, xj = aabbs[j].low.x;
        return xi < xj || (xi == xj && i < j);
    };
    if (order_.size() != n) {  // the first step, or bodies added: sort from scratch
        order_.resize(n);
        for (uint32_t i = 0; i < n; ++i) order_[i] = i;
        std::sort(order_.begin(), order_.end(), before);
    }
    // Insertion sort: boxes move little in a step, so last step's order needs
    // only a few swaps (std::sort would take n log n whatever the input).
    for (uint32_t s = 1; s < n; ++s) {
        const uint32_t moving = order_[s];
        uint32_t t = s;
        for (; t > 0 && before(moving, order_[t - 1]); --t) order_[t] = order_[t - 1];
        order_[t] = moving;
    }
    sorted_.resize(n);
    for (uint32_t s = 0; s < n; ++s)
        sorted_[s] = {aabbs[order_[s]], order_[s], bodies[order_[s]].is_active() ? 1u : 0u};
    // Sweep: the boxes after i in this order that start before i ends along x
    // are the only ones that can overlap it; the first one that starts at or
    // beyond i's end, and every one after it, cannot.
    unsorted_.clear();
    for (uint32_t s = 0; s < n; ++s) {
        const Entry& e = sorted_[s];
        for (uint32_t t = s + 1; t < n && sorted_[t].box.low.x < e.box.high.x; ++t) {
            const Entry& f = sorted_[t];
            if ((e.moves | f.moves) && overlaps(e.box, f.box))
                unsorted_.push_back({std::min(e.index, f.index), std::max(e.index, f.index)});
        }
    }
    // The same order as brute force, by (a, b): a counting sort by a, then
    // each a's few pairs by b.
    counts_.assign(n + 1, 0);
    for (const Pair& p : unsorted_) ++counts_[p.a + 1];
    for (uint32_t i = 0; i < n; ++i) counts_[i + 1] += counts_[i];
    pairs.resize(unsorted_.size());
    for (const Pair& p : unsorted_) pairs[counts_[p.a]++] = p;  // counts_[a]: the end of a's run
    for (uint32_t i = 0, begin = 0; i < n; begin = counts_[i++])
        std::sort(pairs.begin() + begin, pairs.begin() + counts_[i]);
}
// [/sweep]

}  // namespace vkt::physics
