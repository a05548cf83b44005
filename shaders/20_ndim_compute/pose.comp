#version 450
// Chapter 20: the poses, built on the GPU. One workgroup per object, one
// invocation per column of its n x n matrix M = R * diag(scale): the angle of
// every plane at this time (the object's start plus its spin times the time,
// plus what the keys turned), each plane's cosine and sine once, in shared
// memory; then each column, from the unit vector e_c, turned plane by plane
// in the order vkt::ndim::rotation_matrix_by_rows turns rows (a plane (i, j)
// changes only entries i and j of a column). The transform pass reads M and
// the position as before (transform.glsl).

layout(local_size_x = 32) in;  // a column each: --dim is at most 12
layout(constant_id = 0) const int N = 4;
const int PLANES = N * (N - 1) / 2;

// [pose]
layout(push_constant, std430) uniform PosePush {
    float time;  // seconds of spin
} pose_push;
// Per object, 2 PLANES + 2 N floats uploaded once: start angles, spins
// (radians per second), scale, position.
layout(std430, set = 0, binding = 0) readonly buffer Motions { float motions[]; };
// What the keys added, the same for every object, written by the CPU each
// frame: PLANES angles, then N offsets.
layout(std430, set = 0, binding = 1) readonly buffer Steer { float steer[]; };
// Per object, N * N + N floats: M row-major, then the position.
layout(std430, set = 0, binding = 2) writeonly buffer Poses { float poses[]; };

shared vec2 turn[PLANES];  // (cos, sin) of each plane's angle

void main() {
    const uint object = gl_WorkGroupID.x, lane = gl_LocalInvocationID.x;
    const uint motion = object * uint(2 * PLANES + 2 * N);
    for (uint p = lane; p < uint(PLANES); p += gl_WorkGroupSize.x) {
        // SceneObject::at, then Controls::pose: (start + spin * t) + keys.
        const float angle = (motions[motion + p] + motions[motion + PLANES + p] * pose_push.time) +
                            steer[p];
        turn[p] = vec2(cos(angle), sin(angle));
    }
    barrier();
    if (lane >= uint(N)) return;
    float column[N];
    for (int k = 0; k < N; ++k) column[k] = k == int(lane) ? 1.0 : 0.0;
    int p = 0;
    for (int i = 0; i < N; ++i)
        for (int j = i + 1; j < N; ++j, ++p) {
            const float a = column[i], b = column[j];
            column[i] = turn[p].x * a - turn[p].y * b;
            column[j] = turn[p].y * a + turn[p].x * b;
        }
    const uint pose = object * uint(N * N + N);
    const float scale = motions[motion + 2 * PLANES + lane];
    for (int r = 0; r < N; ++r) poses[pose + uint(r * N) + lane] = column[r] * scale;
    poses[pose + uint(N * N) + lane] = motions[motion + 2 * PLANES + N + lane] + steer[PLANES + lane];
}
// [/pose]
