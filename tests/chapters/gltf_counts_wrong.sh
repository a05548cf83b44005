#!/bin/sh
# A stand-in for chapter 26 that miscounts scene.gltf by one triangle: the
# test chapter.26_mesh_shaders.counts_can_fail runs gltf_counts.py on it and
# requires the script to refuse it.
echo "scene.gltf: 1055 triangles, 631 vertices -> 32 meshlets"
