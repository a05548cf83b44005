#version 450
// Chapter 20: transform and project every unique vertex once per frame. One
// invocation per vertex (or a few, on a CPU device): row y of the dispatch
// is the object, x the vertex. The pass itself is transform.glsl.
#extension GL_GOOGLE_include_directive : require
#include "transform.glsl"
