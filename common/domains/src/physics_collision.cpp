#include "vkt/domains/physics_collision.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace vkt::physics {

namespace {

// The sign as +-1, with 0 counted as positive: every choice below must be
// the same on every run, even for a box exactly above another.
float sign_of(float x) {
    return x < 0.0f ? -1.0f : 1.0f;
}

// How strongly the tests below prefer one axis to another: a candidate must be
// shallower than the current choice by 5% plus 5 mm to replace it. Without
// this, two nearly equal axes would take turns from step to step, and the
// contact points (and their warm-start impulses) would jump with them.
constexpr float kRelative = 0.95f, kAbsolute = 0.005f;

}  // namespace

// [sat]
AxisQuery find_contact_axis(const OrientedBox& a, const OrientedBox& b, float margin) {
    // Everything in a's frame: t is b's centre seen from a's, r[i][j] = a_i . b_j
    // is b's axis j along a's axis i.
    const glm::vec3 d = b.centre - a.centre;
    const glm::vec3 t(glm::dot(d, a.rotation[0]), glm::dot(d, a.rotation[1]),
                      glm::dot(d, a.rotation[2]));
    float r[3][3], abs_r[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            r[i][j] = glm::dot(a.rotation[i], b.rotation[j]);
            abs_r[i][j] = std::abs(r[i][j]);
        }
    const glm::vec3 ha = a.half_extents, hb = b.half_extents;

    // Along a unit axis, a box centred at c covers c . axis +- its radius, the
    // sum of its half extents times |its axes . axis|. The gap between the two
    // intervals is |d . axis| - radius_a - radius_b.
    AxisQuery face_a{-FLT_MAX}, face_b{-FLT_MAX}, edge{-FLT_MAX};
    for (int i = 0; i < 3; ++i) {  // a's face normals: a_i
        const float radius_b = hb.x * abs_r[i][0] + hb.y * abs_r[i][1] + hb.z * abs_r[i][2];
        const float gap = std::abs(t[i]) - ha[i] - radius_b;
        if (gap > face_a.separation || gap > margin) {
            face_a = {gap, i, a.rotation[i] * sign_of(t[i])};
            if (gap > margin) return face_a;
        }
    }
    for (int j = 0; j < 3; ++j) {  // b's face normals: b_j
        const float along = t.x * r[0][j] + t.y * r[1][j] + t.z * r[2][j];
        const float radius_a = ha.x * abs_r[0][j] + ha.y * abs_r[1][j] + ha.z * abs_r[2][j];
        const float gap = std::abs(along) - radius_a - hb[j];
        if (gap > face_b.separation || gap > margin) {
            face_b = {gap, 3 + j, b.rotation[j] * sign_of(along)};
            if (gap > margin) return face_b;
        }
    }
    for (int i = 0; i < 3; ++i) {  // an edge of each: a_i x b_j
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            // |a_i x b_j| = sin of the angle between them. Parallel edges give
            // no axis of their own (a face axis covers them), and nearly
            // parallel ones an axis lost in rounding.
            const float length = std::sqrt(r[i1][j] * r[i1][j] + r[i2][j] * r[i2][j]);
            if (length < 1e-3f) continue;
            // In a's frame a_i x b_j = e_i x (r[0][j], r[1][j], r[2][j]), so
            // d . axis and the radii (|a_k . axis|, |b_k . axis|) come out of r.
            const float along = t[i2] * r[i1][j] - t[i1] * r[i2][j];
            const float radius = ha[i1] * abs_r[i2][j] + ha[i2] * abs_r[i1][j] +
                                 hb[j1] * abs_r[i][j2] + hb[j2] * abs_r[i][j1];
            // The gap is (|along| - radius) / length; compared multiplied
            // out, so that only a new best pays for the division.
            const float gap_times_length = std::abs(along) - radius;
            if (gap_times_length > edge.separation * length || gap_times_length > margin * length) {
                const glm::vec3 axis = glm::cross(a.rotation[i], b.rotation[j]) / length;
                edge = {gap_times_length / length, 6 + 3 * i + j, axis * sign_of(along)};
                if (edge.separation > margin) return edge;
            }
        }
    }
    // No axis separates them by more than the margin: the shallowest way out
    // (or the widest gap), a's faces first. Better by 5% of the current
    // choice's size either way: a gap too (speculative contacts), where an
    // edge axis that repeats a face's would otherwise win every tie.
    AxisQuery best = face_a;
    auto better = [&](const AxisQuery& q) {
        return q.separation >
               best.separation + (1.0f - kRelative) * std::abs(best.separation) + kAbsolute;
    };
    if (better(face_b)) best = face_b;
    if (better(edge)) best = edge;
    return best;
}
// [/sat]

namespace {

// A vertex of the polygon being clipped, with the two lines that cross at it:
// 0..3 the incident face's edges (edge e runs from corner e to corner e + 1),
// 4..7 the reference face's sides. Two lines name a point exactly.
struct ClipVertex {
    glm::vec3 p;
    uint8_t line[2];
};

// The line two neighbouring vertices share (the segment between them lies on it).
uint8_t shared_line(const ClipVertex& p, const ClipVertex& q) {
    for (uint8_t l : p.line)
        if (l == q.line[0] || l == q.line[1]) return l;
    return p.line[0];  // not reached: neighbours always share a line
}

// [clip]
// Sutherland-Hodgman: keep the part of the polygon where
// dot(p - origin, axis) <= limit; where an edge crosses, add the crossing.
// A corner outside by less than a millimetre counts as inside: two boxes of
// the same size stacked exactly would otherwise have corners that rounding
// puts now in, now out, and contact points (and ids) that change every step.
constexpr float kClipTolerance = 0.001f;
int clip(const ClipVertex* in, int n, glm::vec3 origin, glm::vec3 axis, float limit, uint8_t side,
         ClipVertex* out) {
    int m = 0;
    for (int i = 0; i < n; ++i) {
        const ClipVertex& p = in[i];
        const ClipVertex& q = in[(i + 1) % n];
        const float dp = glm::dot(p.p - origin, axis) - limit - kClipTolerance;
        const float dq = glm::dot(q.p - origin, axis) - limit - kClipTolerance;
        if (dp <= 0.0f) out[m++] = p;
        if ((dp <= 0.0f) != (dq <= 0.0f)) {
            const float t = dp / (dp - dq);
            out[m++] = {p.p + t * (q.p - p.p), {shared_line(p, q), side}};
        }
    }
    return m;
}
// [/clip]

// More than four points (a quad clipped by a rectangle can leave eight): keep
// the deepest, the one farthest from it, and the two that span the largest
// area on either side of the line between those: four points that hold the
// box as well as all eight would.
void keep_four(ContactPoint* points, uint32_t& count, glm::vec3 normal) {
    if (count <= 4) return;
    uint32_t keep[4] = {0, 0, 0, 0};
    for (uint32_t i = 1; i < count; ++i)
        if (points[i].depth > points[keep[0]].depth) keep[0] = i;
    const glm::vec3 p0 = points[keep[0]].position;
    float far = -1.0f;
    for (uint32_t i = 0; i < count; ++i) {
        const glm::vec3 e = points[i].position - p0;
        if (glm::dot(e, e) > far) far = glm::dot(e, e), keep[1] = i;
    }
    const glm::vec3 line = points[keep[1]].position - p0;
    float most = -FLT_MAX, least = FLT_MAX;
    for (uint32_t i = 0; i < count; ++i) {
        const float area = glm::dot(glm::cross(line, points[i].position - p0), normal);
        if (area > most) most = area, keep[2] = i;
        if (area < least) least = area, keep[3] = i;
    }
    std::sort(keep, keep + 4);  // in the clipper's order, whatever chose them
    ContactPoint kept[4];
    uint32_t n = 0;
    for (int k = 0; k < 4; ++k)
        if (k == 0 || keep[k] != keep[k - 1]) kept[n++] = points[keep[k]];
    std::copy(kept, kept + n, points);
    count = n;
}

// [face-contact]
// The contact of a face of `ref` (axis k, outward normal n, pointing towards
// `inc`) with the face of `inc` that looks most against n.
void face_contact(const OrientedBox& ref, const OrientedBox& inc, int k, glm::vec3 n, float margin,
                  uint32_t id_base, Manifold& out) {
    // The incident face: the axis of inc most parallel to n, on the side
    // facing back against n.
    int j = 0;
    float best = -1.0f;
    for (int axis = 0; axis < 3; ++axis) {
        const float c = std::abs(glm::dot(n, inc.rotation[axis]));
        if (c > best) best = c, j = axis;
    }
    const float inc_sign = -sign_of(glm::dot(n, inc.rotation[j]));
    const glm::vec3 inc_centre = inc.centre + inc_sign * inc.half_extents[j] * inc.rotation[j];
    const glm::vec3 u = inc.rotation[(j + 1) % 3] * inc.half_extents[(j + 1) % 3];
    const glm::vec3 v = inc.rotation[(j + 2) % 3] * inc.half_extents[(j + 2) % 3];
    // Its corners in order around it; corner c lies on edges c - 1 and c.
    ClipVertex polygon[8] = {{inc_centre - u - v, {3, 0}},
                             {inc_centre + u - v, {0, 1}},
                             {inc_centre + u + v, {1, 2}},
                             {inc_centre - u + v, {2, 3}}};
    ClipVertex scratch[8];
    int n_points = 4;
    // The reference face's four sides, as planes through ref's centre.
    const int s = (k + 1) % 3, t = (k + 2) % 3;
    const glm::vec3 sides[4] = {ref.rotation[s], -ref.rotation[s], ref.rotation[t],
                                -ref.rotation[t]};
    const float limits[4] = {ref.half_extents[s], ref.half_extents[s], ref.half_extents[t],
                             ref.half_extents[t]};
    for (uint8_t side = 0; side < 4 && n_points > 0; ++side) {
        n_points = clip(polygon, n_points, ref.centre, sides[side], limits[side], uint8_t(4 + side),
                        scratch);
        std::copy(scratch, scratch + n_points, polygon);
    }
    // What is left lies over the reference face: keep the points below its
    // plane (or above it by less than the margin), halfway between the faces.
    const glm::vec3 face_centre = ref.centre + n * ref.half_extents[k];
    const uint32_t ref_face = uint32_t(2 * k) + (glm::dot(n, ref.rotation[k]) < 0.0f ? 1u : 0u);
    const uint32_t inc_face = uint32_t(2 * j) + (inc_sign < 0.0f ? 1u : 0u);
    ContactPoint points[8];
    uint32_t count = 0;
    for (int i = 0; i < n_points; ++i) {
        const float gap = glm::dot(polygon[i].p - face_centre, n);
        if (gap > margin) continue;
        const uint32_t low = std::min(polygon[i].line[0], polygon[i].line[1]);
        const uint32_t high = std::max(polygon[i].line[0], polygon[i].line[1]);
        points[count++] = {.position = polygon[i].p - 0.5f * gap * n,
                           .depth = -gap,
                           .id = id_base | ref_face << 12 | inc_face << 8 | (low * 8 + high)};
    }
    keep_four(points, count, n);
    out.count = count;
    std::copy(points, points + count, out.points.begin());
}
// [/face-contact]

// [edge-contact]
// Two edges crossing: one point, halfway between their closest points.
void edge_contact(const OrientedBox& a, const OrientedBox& b, int i, int j, const AxisQuery& q,
                  Manifold& out) {
    // The edge of a along a_i nearest to b: at the corner of a's other two
    // axes on b's side; b's edge along b_j likewise, on a's side. Each edge's
    // number (0..11) records which edge it is.
    glm::vec3 pa = a.centre, pb = b.centre;
    uint32_t edge_a = uint32_t(i) * 4, edge_b = uint32_t(j) * 4;
    for (int step = 1; step <= 2; ++step) {
        const int ka = (i + step) % 3, kb = (j + step) % 3;
        const float sa = sign_of(glm::dot(q.normal, a.rotation[ka]));
        const float sb = -sign_of(glm::dot(q.normal, b.rotation[kb]));
        pa += sa * a.half_extents[ka] * a.rotation[ka];
        pb += sb * b.half_extents[kb] * b.rotation[kb];
        edge_a |= (sa < 0.0f ? 1u : 0u) << (step - 1);
        edge_b |= (sb < 0.0f ? 1u : 0u) << (step - 1);
    }
    // The closest points of the lines pa + s da and pb + t db (unit
    // directions), each kept on its edge.
    const glm::vec3 da = a.rotation[i], db = b.rotation[j], r = pa - pb;
    const float cos_ab = glm::dot(da, db), c = glm::dot(da, r), f = glm::dot(db, r);
    const float denominator = std::max(1.0f - cos_ab * cos_ab, 1e-6f);  // not parallel: SAT
    float sa = std::clamp((cos_ab * f - c) / denominator, -a.half_extents[i], a.half_extents[i]);
    const float tb = std::clamp(cos_ab * sa + f, -b.half_extents[j], b.half_extents[j]);
    sa = std::clamp(cos_ab * tb - c, -a.half_extents[i], a.half_extents[i]);
    out.count = 1;
    out.points[0] = {.position = 0.5f * (pa + sa * da + pb + tb * db),
                     .depth = -q.separation,
                     .id = kEdgeContactBit | edge_b << 4 | edge_a};
}
// [/edge-contact]

}  // namespace

bool collide(const OrientedBox& a, const OrientedBox& b, float margin, Manifold& out) {
    const AxisQuery q = find_contact_axis(a, b, margin);
    if (q.separation > margin) return false;
    out.normal = q.normal;
    if (q.axis < 3)  // a's face is the reference
        face_contact(a, b, q.axis, q.normal, margin, 0u, out);
    else if (q.axis < 6)  // b's face: its outward normal points from b to a
        face_contact(b, a, q.axis - 3, -q.normal, margin, kReferenceIsB, out);
    else
        edge_contact(a, b, (q.axis - 6) / 3, (q.axis - 6) % 3, q, out);
    return out.count > 0;
}

// [time-of-impact]
float time_of_impact(const OrientedBox& fixed, glm::vec3 half, const Pose& from, const Pose& to,
                     float target) {
    // Blend the turn the short way round.
    const glm::quat q1 =
        glm::dot(from.orientation, to.orientation) < 0.0f ? -to.orientation : to.orientation;
    auto at = [&](float t) {
        const glm::quat q = glm::normalize((1.0f - t) * from.orientation + t * q1);
        return OrientedBox{glm::mix(from.position, to.position, t), glm::mat3_cast(q), half};
    };
    // How fast any point of the box can close on anything, per unit of t: the
    // centre's move plus the fastest turn times the half diagonal. The
    // blended turn is fastest halfway, at 4 tan(angle / 4) per unit of t.
    const glm::quat turn = q1 * glm::conjugate(from.orientation);
    const float angle =
        2.0f * std::asin(std::min(glm::length(glm::vec3(turn.x, turn.y, turn.z)), 1.0f));
    const float bound = glm::length(to.position - from.position) +
                        4.0f * std::tan(0.25f * angle) * glm::length(half);
    if (bound <= 0.0f) return 1.0f;
    // Conservative advancement: a gap g along any axis cannot close in less
    // than g / bound, so step that far, and again, until the gap is the
    // target (within a quarter of it). A separating axis's gap is never more
    // than the true distance, so no step passes through.
    float t = 0.0f;
    for (int i = 0; i < 32; ++i) {
        const float gap = find_contact_axis(fixed, at(t), FLT_MAX).separation;
        if (gap <= 1.25f * target) return i == 0 ? 1.0f : t;
        t += (gap - target) / bound;
        if (t >= 1.0f) return 1.0f;
    }
    return t;  // a grazing pass: where it got to is still short of the box
}
// [/time-of-impact]

}  // namespace vkt::physics
