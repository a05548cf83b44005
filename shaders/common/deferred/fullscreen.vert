#version 450
// Chapter 16, pass 2: one triangle that covers the whole screen, made from
// gl_VertexIndex alone (no vertex buffer): clip-space corners (-1, -1),
// (3, -1) and (-1, 3). The part outside the screen is clipped away for free,
// and, unlike two triangles, no pixel along a diagonal is shaded twice.
// [fullscreen]
void main() {
    vec2 corner = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);  // (0,0) (2,0) (0,2)
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
// [/fullscreen]
