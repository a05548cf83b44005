#include "vkt/domains/physics_solver.hpp"

#include <algorithm>
#include <cmath>

namespace vkt::physics {

void tangent_basis(glm::vec3 n, glm::vec3& t1, glm::vec3& t2) {
    // Cross n with a world axis it is far from: x when n is mostly along x,
    // y and z otherwise (|n.x| < 1/sqrt(3) leaves the y, z part long enough).
    t1 = std::abs(n.x) >= 0.57735f ? glm::normalize(glm::vec3(n.y, -n.x, 0.0f))
                                   : glm::normalize(glm::vec3(0.0f, n.z, -n.y));
    t2 = glm::cross(n, t1);
}

// [prepare]
void Solver::prepare(Manifold& m, const SolverSettings& s, float dt) {
    Contact c{m.a, m.b, uint32_t(points_.size()), m.count, m.normal, {}, &m};
    tangent_basis(m.normal, c.tangent[0], c.tangent[1]);
    const State& a = states_[m.a];
    const State& b = states_[m.b];
    const glm::mat3& ia = inverse_inertias_[m.a];
    const glm::mat3& ib = inverse_inertias_[m.b];
    // The effective mass along a direction d: 1 / the velocity change a unit
    // impulse along d makes at the point, 1/m_a + 1/m_b plus each body's
    // turning part (r x d) . I^-1 (r x d).
    auto row = [&](glm::vec3 ra, glm::vec3 rb, glm::vec3 d, float impulse) {
        Row r{glm::cross(ra, d), glm::cross(rb, d), {}, {}, 0.0f, impulse};
        r.ia_ra_d = ia * r.ra_d;
        r.ib_rb_d = ib * r.rb_d;
        r.mass = 1.0f / (a.inverse_mass + b.inverse_mass + glm::dot(r.ra_d, r.ia_ra_d) +
                         glm::dot(r.rb_d, r.ib_rb_d));
        return r;
    };
    for (uint32_t k = 0; k < m.count; ++k) {
        const ContactPoint& cp = m.points[k];
        const glm::vec3 ra = cp.position - centres_[m.a];
        const glm::vec3 rb = cp.position - centres_[m.b];
        // Restitution: a point closing faster than the threshold should part
        // at e times that speed. A slower one stops; one still apart by a gap
        // (negative depth, within the margin) may close it in this step.
        const glm::vec3 relative = b.v + glm::cross(b.w, rb) - a.v - glm::cross(a.w, ra);
        const float approach = glm::dot(relative, m.normal);
        const bool bounce = approach < -s.restitution_threshold && cp.depth >= 0.0f;
        // Warm start: last step's impulses at this point (the world copied
        // them in by feature id), unless it bounces now: pushing a bouncing
        // pair apart with last step's resting impulse would add energy.
        const bool warm = s.warm_start && !bounce;
        Point p;
        p.normal = row(ra, rb, m.normal, warm ? cp.normal_impulse : 0.0f);
        for (int t = 0; t < 2; ++t)
            p.tangent[t] = row(ra, rb, c.tangent[t],
                               warm ? glm::dot(cp.friction_impulse, c.tangent[t]) : 0.0f);
        p.target = bounce ? -s.restitution * approach : std::min(cp.depth, 0.0f) / dt;
        // Split impulses: the overlap beyond the slop, a share each step.
        p.push_target = s.push / dt * std::max(cp.depth - s.slop, 0.0f);
        p.push_impulse = 0.0f;
        points_.push_back(p);
    }
    contacts_.push_back(c);
}
// [/prepare]

namespace {

// The relative velocity of the two bodies at the point along d:
// (v_b + w_b x r_b - v_a - w_a x r_a) . d, with (w x r) . d = w . (r x d).
template <class State, class Row>
float velocity_along(const State& a, const State& b, const Row& row, glm::vec3 d) {
    return glm::dot(b.v - a.v, d) + glm::dot(b.w, row.rb_d) - glm::dot(a.w, row.ra_d);
}

// An impulse along d at the point: + on b, - on a (Newton's third law),
// changing each body's velocity by impulse / m and its spin by
// I^-1 (r x d) impulse.
template <class State, class Row>
void apply(State& a, State& b, const Row& row, glm::vec3 d, float impulse) {
    a.v -= (a.inverse_mass * impulse) * d;
    a.w -= impulse * row.ia_ra_d;
    b.v += (b.inverse_mass * impulse) * d;
    b.w += impulse * row.ib_rb_d;
}

}  // namespace

// The three below work on copies of the contact's two bodies, a and b, which
// the loops load once per contact and store back after its last point.

// [solve-friction]
// Friction: the impulse along the contact plane that stops the sliding at
// this point, but in total no larger than mu times the normal impulse. Both
// directions are limited together, so the limit is a circle (Coulomb's cone),
// not a square: a box slides as easily along a diagonal as along an axis.
void Solver::solve_friction(const Contact& c, Point& p, float friction, State& a, State& b) {
    const Row& r1 = p.tangent[0];
    const Row& r2 = p.tangent[1];
    glm::vec2 total(r1.impulse - r1.mass * velocity_along(a, b, r1, c.tangent[0]),
                    r2.impulse - r2.mass * velocity_along(a, b, r2, c.tangent[1]));
    const float limit = friction * p.normal.impulse;
    const float length_squared = glm::dot(total, total);
    if (length_squared > limit * limit) total *= limit / std::sqrt(length_squared);
    // Both directions' changes as one impulse.
    const float d1 = total.x - r1.impulse, d2 = total.y - r2.impulse;
    p.tangent[0].impulse = total.x;
    p.tangent[1].impulse = total.y;
    const glm::vec3 impulse = d1 * c.tangent[0] + d2 * c.tangent[1];
    a.v -= a.inverse_mass * impulse;
    a.w -= d1 * r1.ia_ra_d + d2 * r2.ia_ra_d;
    b.v += b.inverse_mass * impulse;
    b.w += d1 * r1.ib_rb_d + d2 * r2.ib_rb_d;
}
// [/solve-friction]

// [solve-normal]
// The normal impulse: whatever brings the normal velocity at the point to its
// target; the running total may only push (>= 0), never pull.
void Solver::solve_normal(const Contact& c, Point& p, State& a, State& b) {
    const float velocity = velocity_along(a, b, p.normal, c.normal);
    const float total = std::max(p.normal.impulse + p.normal.mass * (p.target - velocity), 0.0f);
    apply(a, b, p.normal, c.normal, total - p.normal.impulse);
    p.normal.impulse = total;
}
// [/solve-normal]

// [solve-push]
// The same along the normal for the push velocities, which move the bodies
// this step and are then forgotten: the overlap goes, no speed is added.
void Solver::solve_push(const Contact& c, Point& p, State& a, State& b) {
    const Row& row = p.normal;
    const float velocity = glm::dot(b.push_v - a.push_v, c.normal) + glm::dot(b.push_w, row.rb_d) -
                           glm::dot(a.push_w, row.ra_d);
    const float total = std::max(p.push_impulse + row.mass * (p.push_target - velocity), 0.0f);
    const float delta = total - p.push_impulse;
    p.push_impulse = total;
    a.push_v -= (a.inverse_mass * delta) * c.normal;
    a.push_w -= delta * row.ia_ra_d;
    b.push_v += (b.inverse_mass * delta) * c.normal;
    b.push_w += delta * row.ib_rb_d;
}
// [/solve-push]

// [shock]
// The last pass, from the ground up (shock propagation). A contact whose
// normal points up (within 60 degrees) is a support: the body below holds up
// the body above. Each body's level is its distance, in supports, from
// something static (breadth first); the supports are visited by the level of
// the lower body, which then counts as static. A tower's bottom box is
// stopped on the floor, the next on the stopped bottom box, and so on up:
// what the passes before could not carry down a tall stack, this pass
// settles. Its impulses change velocities only; the warm start keeps the
// ordinary passes' (an infinitely heavy box below is this pass's fiction).
void Solver::shock_pass(const SolverSettings& s, glm::vec3 up) {
    const auto n = uint32_t(states_.size());
    constexpr uint32_t unreached = 0xffffffffu;
    // Which body of each contact holds up the other (or neither: 2).
    auto lower = [&](const Contact& c) {
        const float along = glm::dot(c.normal, up);  // the normal points from a to b
        return along > 0.5f ? 0u : along < -0.5f ? 1u : 2u;
    };
    // The support graph as adjacency lists, from each body to the bodies it
    // holds up (a counting sort by the lower body).
    start_.assign(n + 1, 0);
    for (const Contact& c : contacts_)
        if (const uint32_t l = lower(c); l != 2) ++start_[(l == 0 ? c.a : c.b) + 1];
    for (uint32_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
    neighbours_.resize(start_[n]);
    cursor_.assign(start_.begin(), start_.end() - 1);
    for (const Contact& c : contacts_)
        if (const uint32_t l = lower(c); l != 2)
            neighbours_[cursor_[l == 0 ? c.a : c.b]++] = l == 0 ? c.b : c.a;
    // Levels: 0 for static (and sleeping) bodies, then breadth first.
    level_.assign(n, unreached);
    queue_.clear();
    for (uint32_t i = 0; i < n; ++i)
        if (states_[i].inverse_mass == 0.0f) level_[i] = 0, queue_.push_back(i);
    for (std::size_t head = 0; head < queue_.size(); ++head) {
        const uint32_t i = queue_[head];
        for (uint32_t k = start_[i]; k < start_[i + 1]; ++k)
            if (level_[neighbours_[k]] == unreached) {
                level_[neighbours_[k]] = level_[i] + 1;
                queue_.push_back(neighbours_[k]);
            }
    }
    // The supports that lead up a level, by the lower body's level (ties by
    // index); the others are left to the ordinary passes.
    order_.clear();
    for (uint32_t i = 0; i < contacts_.size(); ++i) {
        const Contact& c = contacts_[i];
        const uint32_t l = lower(c);
        if (l == 2) continue;
        const uint32_t below = l == 0 ? c.a : c.b, above = l == 0 ? c.b : c.a;
        if (level_[below] != unreached && level_[below] < level_[above])
            order_.push_back(uint64_t(level_[below]) << 32 | i);
    }
    std::sort(order_.begin(), order_.end());
    // [/shock]

    // [shock-solve]
    saved_mass_.resize(n);
    for (uint32_t i = 0; i < n; ++i) saved_mass_[i] = states_[i].inverse_mass;
    for (uint64_t key : order_) {
        const Contact& c = contacts_[uint32_t(key)];
        const bool a_frozen = lower(c) == 0;
        // The lower body is now static: no mass, no spin from any impulse.
        states_[a_frozen ? c.a : c.b].inverse_mass = 0.0f;
        const float moving_mass = states_[a_frozen ? c.b : c.a].inverse_mass;
        Point local[4];
        for (uint32_t k = 0; k < c.count; ++k) {
            local[k] = points_[c.first + k];
            for (Row* r : {&local[k].normal, &local[k].tangent[0], &local[k].tangent[1]}) {
                (a_frozen ? r->ia_ra_d : r->ib_rb_d) = glm::vec3(0.0f);
                const float turning =
                    a_frozen ? glm::dot(r->rb_d, r->ib_rb_d) : glm::dot(r->ra_d, r->ia_ra_d);
                r->mass = 1.0f / (moving_mass + turning);
            }
        }
        // One body against a fixed one: a small problem, solved to
        // convergence by passes back and forth over its points.
        State a = states_[c.a], b = states_[c.b];
        const int passes = std::min(s.shock_iterations, 3 * int(c.count));
        for (int iteration = 0; iteration < passes; ++iteration)
            for (uint32_t k = 0; k < c.count; ++k) {
                Point& p = local[iteration % 2 ? c.count - 1 - k : k];
                solve_friction(c, p, s.friction, a, b);
                solve_normal(c, p, a, b);
            }
        states_[c.a] = a;
        states_[c.b] = b;
    }
    for (uint32_t i = 0; i < n; ++i) states_[i].inverse_mass = saved_mass_[i];
    // [/shock-solve]
}

// [solve]
void Solver::solve(std::span<Body> bodies, std::span<Manifold> manifolds, const SolverSettings& s,
                   float dt, glm::vec3 gravity) {
    const std::size_t n = bodies.size();
    states_.resize(n);
    centres_.resize(n);
    inverse_inertias_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Body& body = bodies[i];
        const bool moves = body.is_active();  // static and sleeping: infinitely heavy
        states_[i] = {body.velocity, body.angular_velocity, glm::vec3(0.0f), glm::vec3(0.0f),
                      moves ? body.inverse_mass : 0.0f};
        centres_[i] = body.position;
        inverse_inertias_[i] =
            moves ? world_inverse_inertia(rotation(body), body.inverse_inertia) : glm::mat3(0.0f);
    }
    contacts_.clear();
    points_.clear();
    for (Manifold& m : manifolds)
        if (bodies[m.a].is_active() || bodies[m.b].is_active()) prepare(m, s, dt);

    // Warm start: apply last step's impulses first. A stack's weight then need
    // not be found again from nothing each step; it builds up over steps.
    for (const Contact& c : contacts_)
        for (uint32_t k = 0; k < c.count; ++k) {
            const Point& p = points_[c.first + k];
            State& a = states_[c.a];
            State& b = states_[c.b];
            apply(a, b, p.normal, c.normal, p.normal.impulse);
            for (int t = 0; t < 2; ++t)
                apply(a, b, p.tangent[t], c.tangent[t], p.tangent[t].impulse);
        }
    // Every point, several times over: each pass fixes what the last broke
    // elsewhere. Friction before the normal, so that the normal impulse, which
    // keeps the boxes apart, has the last word. Every other pass runs
    // backwards, so that no contact is always solved first.
    const std::size_t count = contacts_.size();
    for (int iteration = 0; iteration < s.iterations; ++iteration) {
        const bool backwards = iteration % 2 != 0;
        const bool push = iteration < s.push_iterations;
        for (std::size_t i = 0; i < count; ++i) {
            const Contact& c = contacts_[backwards ? count - 1 - i : i];
            State a = states_[c.a], b = states_[c.b];
            for (uint32_t k = 0; k < c.count; ++k) {
                Point& p = points_[c.first + (backwards ? c.count - 1 - k : k)];
                solve_friction(c, p, s.friction, a, b);
                solve_normal(c, p, a, b);
                if (push) solve_push(c, p, a, b);
            }
            states_[c.a] = a;
            states_[c.b] = b;
        }
    }
    // Keep the impulses for next step's warm start (before the shock pass).
    for (const Contact& c : contacts_)
        for (uint32_t k = 0; k < c.count; ++k) {
            const Point& p = points_[c.first + k];
            ContactPoint& cp = c.source->points[k];
            cp.normal_impulse = p.normal.impulse;
            cp.friction_impulse =
                p.tangent[0].impulse * c.tangent[0] + p.tangent[1].impulse * c.tangent[1];
        }
    if (s.shock_iterations > 0 && glm::dot(gravity, gravity) > 0.0f)
        shock_pass(s, -glm::normalize(gravity));
    for (std::size_t i = 0; i < n; ++i)
        if (bodies[i].is_active()) {
            bodies[i].velocity = states_[i].v;
            bodies[i].angular_velocity = states_[i].w;
        }
}
// [/solve]

}  // namespace vkt::physics
