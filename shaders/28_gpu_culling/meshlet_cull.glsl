// Chapter 28's task path, --meshlet-cull on: the tests a meshlet of a kept
// instance must pass before a mesh workgroup is launched for it. Chapter 26
// culls a meshlet by its sphere and its normal cone; here the meshlet is
// one of an instance's, so each test first brings the two into one space.
// Included after instance_cull.glsl (occluded) and task_data.glsl (Meshlet,
// OUTSIDE .. KEPT). The camera is an argument: --view culled tests for one
// camera and draws from another.

// [meshlet-cull]
uint cull_meshlet(Instance o, Meshlet m, mat4 clip_from_world, vec3 eye_in_world) {
    // The sphere in the world: its centre placed as place() places a vertex
    // (scaled, turned about +y, moved), its radius scaled by the largest scale.
    float c = cos(o.position_yaw.w), s = sin(o.position_yaw.w);
    vec3 p = m.centre * o.scale.xyz;
    vec3 centre = o.position_yaw.xyz + vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
    float radius = m.radius * max(o.scale.x, max(o.scale.y, o.scale.z));

    // Frustum: outside when the whole sphere lies beyond one plane. A plane
    // is a row combination of the matrix; divided by its normal's length,
    // it gives the distance in metres (as the CPU's count_in_frustum).
    if (push.mode >= 1) {
        mat4 t = transpose(clip_from_world);  // t[r]: row r
        vec4 planes[6] = vec4[6](t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[2],
                                 t[3] - t[2]);
        for (int k = 0; k < 6; ++k)
            if (dot(planes[k].xyz, centre) + planes[k].w < -radius * length(planes[k].xyz))
                return OUTSIDE;
    }

    // Normal cone: every triangle faces away from the eye. Whether a triangle
    // faces the eye is unchanged by scaling, turning or moving both (the
    // sign of dot(normal, point - eye) survives any such map), so the eye is
    // taken into the mesh's own space, where the cone and the sphere were
    // built, and chapter 26's test is made there: the perspective one, from
    // the eye's position, never the orthographic one from a view direction.
    vec3 d = eye_in_world - o.position_yaw.xyz;
    vec3 eye = vec3(c * d.x - s * d.z, d.y, s * d.x + c * d.z) / o.scale.xyz;
    vec3 to_centre = m.centre - eye;
    if (dot(to_centre, m.cone_axis) >= m.cone_cutoff * length(to_centre) + m.radius)
        return FACING_AWAY;

    // Occlusion, in the late pass only (the pyramid is this frame's): the
    // sphere's box against the pyramid, with the instances' own test.
    if (push.mode == 2 && push.phase >= 1) {
        vec4 corners[8];
        for (int k = 0; k < 8; ++k) {
            vec3 side = vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0,
                             (k & 4) != 0 ? 1.0 : -1.0);
            corners[k] = clip_from_world * vec4(centre + side * radius, 1.0);
        }
        if (occluded(corners)) return HIDDEN;
    }
    return KEPT;
}
// [/meshlet-cull]
