// Octahedral normal encoding (Meyer et al., "On floating-point normal
// vectors", 2010): a unit vector in two numbers in [-1, 1]. The twin for the
// CPU is oct_decode in chapters/16_deferred/gbuffer.hpp.
// [octahedral]
vec2 sign_not_zero(vec2 v) {
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

// Project onto the octahedron |x| + |y| + |z| = 1, then fold the lower half
// (z < 0) over the upper one: the square [-1, 1]^2 covers the whole sphere.
vec2 oct_encode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    return n.z >= 0.0 ? n.xy : (1.0 - abs(n.yx)) * sign_not_zero(n.xy);
}

vec3 oct_decode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * sign_not_zero(n.xy);
    return normalize(n);
}
// [/octahedral]
