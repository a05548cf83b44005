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

// [soft]
void soft_constraint(float hertz, float zeta, float h, float& bias_rate, float& mass_scale,
                     float& impulse_scale) {
    // A spring of angular frequency omega and damping ratio zeta on the
    // overlap, stepped implicitly over h (book/14d_solver.md derives it).
    const float omega = 2.0f * 3.14159265f * hertz;
    const float a1 = 2.0f * zeta + h * omega;
    const float a2 = h * omega * a1;
    const float a3 = 1.0f / (1.0f + a2);
    bias_rate = omega / a1;
    mass_scale = a2 * a3;
    impulse_scale = a3;
}
// [/soft]

// [prepare]
void Solver::prepare(Manifold& m, const SolverSettings& s) {
    const State& a = states_[m.a];
    const State& b = states_[m.b];
    Contact c{m.a,
              m.b,
              uint32_t(points_.size()),
              m.count,
              m.normal,
              {},
              a.inverse_mass == 0.0f || b.inverse_mass == 0.0f,
              &m};
    tangent_basis(m.normal, c.tangent[0], c.tangent[1]);
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
        // Warm start: last step's impulses at this point (the world copied
        // them in by feature id).
        Point p;
        p.normal = row(ra, rb, m.normal, s.warm_start ? cp.normal_impulse : 0.0f);
        for (int t = 0; t < 2; ++t)
            p.tangent[t] = row(ra, rb, c.tangent[t],
                               s.warm_start ? glm::dot(cp.friction_impulse, c.tangent[t]) : 0.0f);
        // Restitution is decided after the sub-steps from the normal velocity
        // measured now, before anything has changed it: a point found while a
        // gap remains bounces as well as one found overlapping.
        const glm::vec3 relative = b.v + glm::cross(b.w, rb) - a.v - glm::cross(a.w, ra);
        p.approach = glm::dot(relative, m.normal);
        p.separation = -cp.depth;
        p.most_impulse = 0.0f;
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

// [solve-contacts]
// One pass over every contact: the normal at each of its points, then
// friction at each. `soft`: with the
// spring that pushes overlap apart; without it (relaxing), the normal only
// stops the approach, so the push's speed does not stay in the bodies.
// Each pass starts at the next of a contact's points: the point solved first
// in a pass takes more of the load than its share (the others then correct
// for it), and always the same one would tip the box a little towards it,
// every pass. A 20-box tower, awake, swayed 1-2 mm at the top that way; with
// the start going round, 0.03 mm in 30 s.
void Solver::solve_contacts(const SolverSettings& s, const Group& g, float h, bool soft) {
    const uint32_t start = g.passes++;
    for (const Contact& c : g.contacts) {
        State a = states_[c.a], b = states_[c.b];  // copies, stored back below
        const Softness& spring = c.static_other ? soft_static_ : soft_;
        // The first point this pass, then round: at most 4 points, so no
        // division per point (the modulo per point cost 4% of a step).
        uint32_t at = c.count == 4 ? start & 3u : start % c.count;
        for (uint32_t i = 0; i < c.count; ++i, at = at + 1 == c.count ? 0 : at + 1) {
            Point& p = points_[c.first + at];
            // The separation now, to first order: the step's start plus how
            // far the two bodies have moved and turned along the normal since.
            Row& n = p.normal;
            const float separation = p.separation + glm::dot(b.moved - a.moved, c.normal) +
                                     glm::dot(b.turned, n.rb_d) - glm::dot(a.turned, n.ra_d);
            float bias = 0.0f, mass_scale = 1.0f, impulse_scale = 0.0f;
            if (separation > 0.0f) {
                bias = separation / h;  // speculative: may close the gap, no more
            } else if (soft) {
                bias = std::max(spring.bias_rate * separation, -s.push_speed);
                mass_scale = spring.mass_scale;
                impulse_scale = spring.impulse_scale;
            }
            // The normal impulse: soft, so it only moves the velocity part of
            // the way to its target, and the running total only pushes.
            const float velocity = velocity_along(a, b, n, c.normal);
            const float change =
                -n.mass * mass_scale * (velocity + bias) - impulse_scale * n.impulse;
            const float normal = std::max(n.impulse + change, 0.0f);
            apply(a, b, n, c.normal, normal - n.impulse);
            n.impulse = normal;
            p.most_impulse = std::max(p.most_impulse, normal);
        }
        // Then friction, limited by the normal impulses just found.
        for (uint32_t k = 0; k < c.count; ++k) {
            Point& p = points_[c.first + k];
            // Friction: the impulse along the contact plane that stops the
            // sliding, no larger in total than mu times the normal impulse.
            // Both directions together, so the limit is a circle (Coulomb's
            // cone): a box slides as easily along a diagonal as along an axis.
            Row& r1 = p.tangent[0];
            Row& r2 = p.tangent[1];
            glm::vec2 total(r1.impulse - r1.mass * velocity_along(a, b, r1, c.tangent[0]),
                            r2.impulse - r2.mass * velocity_along(a, b, r2, c.tangent[1]));
            const float limit = s.friction * p.normal.impulse;
            const float length_squared = glm::dot(total, total);
            if (length_squared > limit * limit) total *= limit / std::sqrt(length_squared);
            const float d1 = total.x - r1.impulse, d2 = total.y - r2.impulse;
            r1.impulse = total.x;
            r2.impulse = total.y;
            const glm::vec3 impulse = d1 * c.tangent[0] + d2 * c.tangent[1];
            a.v -= a.inverse_mass * impulse;
            a.w -= d1 * r1.ia_ra_d + d2 * r2.ia_ra_d;
            b.v += b.inverse_mass * impulse;
            b.w += d1 * r1.ib_rb_d + d2 * r2.ib_rb_d;
        }
        states_[c.a] = a;
        states_[c.b] = b;
    }
}
// [/solve-contacts]

// [restitution]
constexpr int kRestitutionPasses = 16;
// After the sub-steps: a point that was closing faster than the threshold
// when the step began, and that did touch (a speculative point that never
// got an impulse did not), leaves at e times that speed.
void Solver::restitution(const SolverSettings& s) {
    if (s.restitution == 0.0f) return;
    // Only the points that bounce (few: those hit this step) take part.
    bouncing_.clear();
    for (uint32_t i = 0; i < uint32_t(contacts_.size()); ++i)
        for (uint32_t k = 0; k < contacts_[i].count; ++k) {
            const Point& p = points_[contacts_[i].first + k];
            if (p.approach < -s.restitution_threshold && p.most_impulse > 0.0f)
                bouncing_.emplace_back(i, contacts_[i].first + k);
        }
    // Many passes, as for any impulse solved point by point: a box landing
    // on an edge or three corners needs them to give each point e (four
    // passes left a three-corner landing 25% off), and they cost little.
    for (int pass = 0; pass < kRestitutionPasses; ++pass)
        for (const auto& [contact, point] : bouncing_) {
            const Contact& c = contacts_[contact];
            State& a = states_[c.a];
            State& b = states_[c.b];
            Point& p = points_[point];
            Row& n = p.normal;
            const float velocity = velocity_along(a, b, n, c.normal);
            const float change = -n.mass * (velocity + s.restitution * p.approach);
            const float normal = std::max(n.impulse + change, 0.0f);
            apply(a, b, n, c.normal, normal - n.impulse);
            n.impulse = normal;
        }
}
// [/restitution]

// [substeps]
void Solver::run(std::span<Body> bodies, const Group& g, const SolverSettings& s, float dt,
                 glm::vec3 gravity) {
    const float h = dt / float(g.substeps);
    // The spring: no stiffer than a quarter of the sub-step rate (stiffer
    // ones are not stable). Against static bodies twice as stiff, as in
    // Box2D, but under the same cap: at the default 120 Hz and 4 sub-steps
    // the spring is at the cap already, and the two are the same.
    const float hertz = std::min(g.hertz, 0.25f / h);
    soft_constraint(hertz, s.damping_ratio, h, soft_.bias_rate, soft_.mass_scale,
                    soft_.impulse_scale);
    soft_constraint(std::min(2.0f * hertz, 0.25f / h), s.damping_ratio, h, soft_static_.bias_rate,
                    soft_static_.mass_scale, soft_static_.impulse_scale);
    const float damping = 1.0f / (1.0f + h * s.angular_damping);
    for (int sub = 0; sub < g.substeps; ++sub) {
        // Gravity and damping, for every moving body (woken ones included).
        for (uint32_t i : g.movers) {
            states_[i].v += gravity * h;
            states_[i].w *= damping;
        }
        // Warm start: the impulses so far (last step's, then last sub-step's)
        // first, so that a stack's weight need not be found again each time.
        for (const Contact& c : g.contacts)
            for (uint32_t k = 0; k < c.count; ++k) {
                const Point& p = points_[c.first + k];
                State& a = states_[c.a];
                State& b = states_[c.b];
                apply(a, b, p.normal, c.normal, p.normal.impulse);
                for (int t = 0; t < 2; ++t)
                    apply(a, b, p.tangent[t], c.tangent[t], p.tangent[t].impulse);
            }
        for (int i = 0; i < g.iterations; ++i) solve_contacts(s, g, h, true);
        // Move and turn with the solved velocities.
        for (uint32_t i : g.movers) {
            State& state = states_[i];
            integrate_position(bodies[i], state.v, state.w, h);
            state.moved += state.v * h;
            state.turned += state.w * h;
        }
        for (int i = 0; i < s.relax_iterations; ++i)
            solve_contacts(s, g, h, false);  // relax: the push's speed goes
    }
}
// [/substeps]

// [step]
void Solver::step(std::span<Body> bodies, std::span<Manifold> manifolds, const SolverSettings& s,
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
        if (bodies[m.a].is_active() || bodies[m.b].is_active()) prepare(m, s);

    // The islands these springs hold take the chapter's sub-steps; those
    // that need stiffer ones (find_needs) take more, shorter ones with the
    // spring stiffer in step. Islands share no moving body, so each group
    // runs on its own, and both advance the whole step dt.
    find_needs(s);
    const int substeps = std::max(s.substeps, 1);
    const std::span<const uint32_t> movers(movers_);
    const std::span<const Contact> contacts(contacts_);
    run(bodies,
        {substeps, s.iterations, s.contact_hertz, movers.first(normal_movers_),
         contacts.first(normal_contacts_), passes_[0]},
        s, dt, gravity);
    if (normal_movers_ < movers_.size()) {
        const int stiff = std::max(s.stiff_substeps, substeps);
        run(bodies,
            {stiff, s.stiff_iterations, s.contact_hertz * float(stiff) / float(substeps),
             movers.subspan(normal_movers_), contacts.subspan(normal_contacts_), passes_[1]},
            s, dt, gravity);
    }
    restitution(s);
    // Keep the impulses for next step's warm start.
    for (const Contact& c : contacts_)
        for (uint32_t k = 0; k < c.count; ++k) {
            const Point& p = points_[c.first + k];
            ContactPoint& cp = c.source->points[k];
            cp.normal_impulse = p.normal.impulse;
            cp.friction_impulse =
                p.tangent[0].impulse * c.tangent[0] + p.tangent[1].impulse * c.tangent[1];
        }
    for (std::size_t i = 0; i < n; ++i)
        if (bodies[i].is_active()) {
            bodies[i].velocity = states_[i].v;
            bodies[i].angular_velocity = states_[i].w;
        }
}
// [/step]

}  // namespace vkt::physics
