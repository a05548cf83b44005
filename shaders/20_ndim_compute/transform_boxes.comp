#version 450
// Chapter 20, --raster binned: the transform pass (transform.glsl), which
// also merges each object's box on the screen, the pixels its lines may
// touch, for the bin pass (bin.comp): with subgroup operations, which a
// device must offer in compute shaders for --raster binned (main.cpp).
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#define BOXES
#include "transform.glsl"
