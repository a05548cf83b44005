// Chapter 28's test of one instance, which the cull pass (cull.comp) and
// the task path's task shader (instances.task) both make: its box against
// the frustum and, in the late pass, against the depth pyramid; the counts
// it keeps, and the list it joins. Included after culling_data.glsl.

// [counts]
// counts[0..2]: the three lists' lengths (the draw counts); counts[3]: the
// instances inside the frustum; counts[4]: those of them occluded;
// counts[5..9]: the task path's meshlets (instances.task).
layout(std430, set = 0, binding = 3) buffer Counts { uint counts[16]; };
// visible[i]: instance i passed the last late pass (was seen last frame).
layout(std430, set = 0, binding = 4) buffer Visible { uint visible[]; };
// [/counts]
layout(set = 0, binding = 5) uniform sampler2D pyramid;

// [frustum]
// The box's eight corners in clip space. It is outside when all of them lie
// beyond one plane of the clip volume (-w <= x, y <= w and, reversed depth,
// 0 <= z <= w): then no part of it can reach the screen.
bool in_frustum(vec4 corners[8]) {
    for (int plane = 0; plane < 6; ++plane) {
        int beyond = 0;
        for (int k = 0; k < 8; ++k) {
            vec4 p = corners[k];
            float d = plane == 0 ? p.x + p.w : plane == 1 ? p.w - p.x
                    : plane == 2 ? p.y + p.w : plane == 3 ? p.w - p.y
                    : plane == 4 ? p.z : p.w - p.z;
            beyond += d < 0.0 ? 1 : 0;
        }
        if (beyond == 8) return false;
    }
    return true;
}
// [/frustum]

// [occlusion]
// Hidden when the box's nearest point lies behind the farthest depth drawn
// over every pixel its projection may touch. Depth is reversed (1 near, 0
// far): the nearest corner has the largest depth, the farthest depth drawn
// is the pyramid's min. The level chosen is the finest at which those
// pixels fall into at most 2 x 2 texels, and all of them are read.
bool occluded(vec4 corners[8]) {
    vec2 lo = vec2(1e30), hi = vec2(-1e30);
    float nearest = 0.0;
    for (int k = 0; k < 8; ++k) {
        if (corners[k].z > corners[k].w) return false;  // before the near plane
        vec3 ndc = corners[k].xyz / corners[k].w;
        lo = min(lo, ndc.xy);
        hi = max(hi, ndc.xy);
        nearest = max(nearest, ndc.z);
    }
    // The pixels whose centres the projection may cover, clamped to the screen.
    ivec2 size = ivec2(push.viewport);
    // Level L's texel t covers pixels [t, t + 1) * 2^(L + 1) (pyramid.hpp).
    ivec2 p0 = clamp(ivec2(floor((lo * 0.5 + 0.5) * vec2(size))), ivec2(0), size - 1);
    ivec2 p1 = clamp(ivec2(floor((hi * 0.5 + 0.5) * vec2(size))), ivec2(0), size - 1);
    int level = 0;
    ivec2 t0 = p0 >> 1, t1 = p1 >> 1;
    while (level + 1 < int(push.levels) && any(greaterThan(t1 - t0, ivec2(1)))) {
        ++level;
        t0 >>= 1;
        t1 >>= 1;
    }
    float farthest = min(min(texelFetch(pyramid, t0, level).r,
                             texelFetch(pyramid, ivec2(t1.x, t0.y), level).r),
                         min(texelFetch(pyramid, ivec2(t0.x, t1.y), level).r,
                             texelFetch(pyramid, t1, level).r));
    return nearest < farthest;
}
// [/occlusion]

// [cull]
// Which list instance i joins in this pass (NOT_DRAWN: none). The counts of
// the instances in the frustum and of those occluded are kept here; the
// caller counts what it draws.
const uint NOT_DRAWN = 3;
uint cull_instance(uint i) {
    Instance o = instances[i];
    vec4 corners[8];
    for (int k = 0; k < 8; ++k) {
        vec3 s = vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0,
                      (k & 4) != 0 ? 1.0 : -1.0);
        corners[k] = push.clip_from_world * vec4(o.box_centre.xyz + s * o.box_half.xyz, 1.0);
    }
    bool inside = in_frustum(corners);
    if (push.mode < 2) {  // one pass: everything, or what the frustum keeps
        if (inside) atomicAdd(counts[3], 1);
        return push.mode == 0 || inside ? EARLY : NOT_DRAWN;
    }
    if (push.phase == 0) {
        // Early: what was seen last frame and is still in the frustum, drawn
        // first, so that its depth can build the pyramid.
        return inside && visible[i] != 0 ? EARLY : NOT_DRAWN;
    }
    // Late: everything in the frustum, against the pyramid of the early
    // draws; what is seen and was not drawn early is drawn now.
    bool seen = inside && !occluded(corners);
    if (inside) atomicAdd(counts[3], 1);
    uint list = NOT_DRAWN;
    if (inside && !seen) {
        atomicAdd(counts[4], 1);
        if (push.list == CULLED) list = CULLED;
    }
    if (seen && visible[i] == 0) list = LATE;
    visible[i] = seen ? 1 : 0;
    return list;
}
// [/cull]
