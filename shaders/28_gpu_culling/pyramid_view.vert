#version 460

// One triangle over the whole screen (--view pyramid).
void main() {
    vec2 p = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}
