// A meshlet and a vertex as task and mesh shaders read them: vkt::Meshlet
// (common/scene/include/vkt/scene/meshlets.hpp, taught by chapter 26) and a
// vertex's position and normal, each padded to a vec4. Chapters 26 and 28.
#ifndef VKT_MESHLET_GLSL
#define VKT_MESHLET_GLSL
struct Vertex {
    vec4 position;
    vec4 normal;
};
struct Meshlet {
    vec3 centre;  // the bounding sphere
    float radius;
    vec3 cone_axis;  // the normal cone
    float cone_cutoff;
    uint vertex_offset;
    uint vertex_count;
    uint triangle_offset;
    uint triangle_count;
};
#endif
