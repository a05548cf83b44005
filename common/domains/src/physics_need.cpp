// Sub-steps per island, by need (chapter 14, book/14d_solver.md): which
// islands this step get the stiff sub-steps.
#include "vkt/domains/physics_solver.hpp"

#include <algorithm>

namespace vkt::physics {

// [needs]
// An island needs stiffer springs than the chapter's when a spring's give,
// magnified, can tip or twist it: a tall support chain (every contact in it
// tilts a little under the load above, and the tilts add up the chain) or a
// load far heavier than the body under it (the light body's spring is
// stiff for its own mass only). Islands here are this step's: moving
// bodies joined by contacts, static and sleeping ones joining none.
void Solver::find_needs(const SolverSettings& s) {
    const auto n = uint32_t(states_.size());
    auto moves = [&](uint32_t i) { return states_[i].inverse_mass > 0.0f; };
    parent_.resize(n);
    for (uint32_t i = 0; i < n; ++i) parent_[i] = i;
    auto find = [&](uint32_t i) {
        while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
        return i;
    };
    // The contacts between two moving bodies, as lists per body; and the
    // islands, each labelled by its lowest body (the same on every run).
    first_neighbour_.assign(n + 1, 0);
    for (const Contact& c : contacts_)
        if (moves(c.a) && moves(c.b)) ++first_neighbour_[c.a + 1], ++first_neighbour_[c.b + 1];
    for (uint32_t i = 0; i < n; ++i) first_neighbour_[i + 1] += first_neighbour_[i];
    neighbours_.resize(first_neighbour_[n]);
    queue_.assign(first_neighbour_.begin(), first_neighbour_.end() - 1);  // fill positions
    stiff_.assign(n, 0);
    const bool enabled = s.stiff_substeps > s.substeps;
    for (const Contact& c : contacts_) {
        if (!moves(c.a) || !moves(c.b)) continue;
        neighbours_[queue_[c.a]++] = c.b;
        neighbours_[queue_[c.b]++] = c.a;
        const uint32_t ra = find(c.a), rb = find(c.b);
        parent_[std::max(ra, rb)] = std::min(ra, rb);
        // Unequal masses in contact: the island's root is marked.
        const float heavy = std::max(states_[c.a].inverse_mass, states_[c.b].inverse_mass);
        const float light = std::min(states_[c.a].inverse_mass, states_[c.b].inverse_mass);
        if (enabled && heavy >= s.stiff_mass_ratio * light) stiff_[c.a] = stiff_[c.b] = 1;
    }
    // Support height, breadth first: 1 for a moving body that touches
    // something static (or asleep), then one more for each contact up.
    height_.assign(n, 0);
    queue_.clear();
    for (const Contact& c : contacts_)
        for (uint32_t i : {c.a, c.b})
            if (moves(i) && !moves(i == c.a ? c.b : c.a) && height_[i] == 0) {
                height_[i] = 1;
                queue_.push_back(i);
            }
    for (std::size_t next = 0; next < queue_.size(); ++next) {
        const uint32_t i = queue_[next];
        if (enabled && int(height_[i]) >= s.stiff_height) stiff_[i] = 1;
        for (uint32_t k = first_neighbour_[i]; k < first_neighbour_[i + 1]; ++k)
            if (height_[neighbours_[k]] == 0) {
                height_[neighbours_[k]] = height_[i] + 1;
                queue_.push_back(neighbours_[k]);
            }
    }
    // A marked body makes its whole island stiff.
    for (uint32_t i = 0; i < n; ++i)
        if (stiff_[i]) stiff_[find(i)] = 1;
    for (uint32_t i = 0; i < n; ++i) stiff_[i] = stiff_[find(i)];
    // The moving bodies and the contacts, the normal islands' first, each
    // in index order as before.
    movers_.clear();
    for (int group = 0; group < 2; ++group) {
        for (uint32_t i = 0; i < n; ++i)
            if (moves(i) && stiff_[i] == group) movers_.push_back(i);
        if (group == 0) normal_movers_ = movers_.size();
    }
    auto stiff_contact = [&](const Contact& c) { return stiff_[c.a] || stiff_[c.b]; };
    normal_contacts_ =
        std::size_t(std::stable_partition(contacts_.begin(), contacts_.end(),
                                          [&](const Contact& c) { return !stiff_contact(c); }) -
                    contacts_.begin());
}
// [/needs]

}  // namespace vkt::physics
