# Chapter 26: the knot (assets/gltf/knot.glb) cut into 389 meshlets, drawn by
# task and mesh shaders that cull whole meshlets.
#
# The counts: after 10 frames at 320x240 the whole knot is in view, so no
# meshlet lies outside the frustum, and 65 face away from the camera. The
# chapter prints what the task shader counted and what the CPU finds for the
# same view (meshlets.hpp, the same tests); both must say so. The top-left
# corner is the clear colour, linear (0.55, 0.62, 0.70), stored sRGB-encoded.
set(VKT_26_PIXEL PIXEL 0,0,196,206,218,1)
set(VKT_26_COUNTS
  "knot.glb: 30720 triangles, 15729 vertices -> 389 meshlets \\(at most 64 vertices and 124 triangles each; the device allows [0-9]+ and [0-9]+\\)"
  "the last frame culled 65 of 389 meshlets \\(0 outside the frustum, 65 facing away\\), drew 324 meshlets"
  "the CPU culls 65 for that view \\(0 outside the frustum, 65 facing away\\)")
# lavapipe prefers each invocation to write its own vertex and primitive, in
# workgroups of up to 128: the mesh workgroup is 128 there (mesh_limits.hpp;
# other devices: tests/unit/test_mesh_limits.cpp).
vkt_chapter_test(chapter.26_mesh_shaders 26_mesh_shaders GOLDEN BLESS ${VKT_26_PIXEL}
  ARGS ${headless} EXPECT ${VKT_26_COUNTS} "task and mesh shaders, lit view, culling on"
  "mesh shader outputs 3072 of [0-9]+ bytes \\(granularity 1 vertices, 1 primitives\\); mesh workgroups of 128 \\(one invocation per vertex and per triangle")
vkt_chapter_test(chapter.26_mesh_shaders.offscreen 26_mesh_shaders SAME_AS chapter.26_mesh_shaders ${VKT_26_PIXEL}
  ARGS ${offscreen} EXPECT ${VKT_26_COUNTS})
vkt_chapter_window_test(26_mesh_shaders PIXEL 0,0,196,206,218,1)
# The meshlet view: each meshlet in its own colour; its own golden.
vkt_chapter_test(chapter.26_mesh_shaders.meshlets 26_mesh_shaders
  GOLDEN_FILE 26_mesh_shaders_meshlets.png LABELS bless ${VKT_26_PIXEL}
  ARGS ${headless} --view meshlets EXPECT "meshlets view")
# --view culled at --turn 30: every meshlet drawn, from a second camera
# opposite the first across the knot, coloured by the task shader's verdict
# for the first: outside its frustum (0.75, 0.05, 0.85), stored (225, 63,
# 237); facing away (1, 0.75, 0), (255, 225, 0); kept, the knot's colour lit
# as ever, its underside, which only the ambient term lights: (111, 93, 69).
# Flat colours, depth-tested. (109, 109) is on the part of the knot the
# turned gaze leaves (on the left, seen from the far side), (200, 122) on a
# far side of the tube that the cone test culls, (212, 76) on a kept
# meshlet. The counts are the lit run's at --turn 30, with all 389 drawn.
vkt_chapter_test(chapter.26_mesh_shaders.view_culled 26_mesh_shaders
  GOLDEN_FILE 26_mesh_shaders_culled.png LABELS bless
  PIXEL 0,0,196,206,218,1 109,109,225,63,237 200,122,255,225,0 212,76,111,93,69,1
  ARGS ${headless} --turn 30 --view culled
  EXPECT "task and mesh shaders, culled view, culling on"
         "would have culled 174 of 389 meshlets \\(127 outside the frustum, 47 facing away\\), drew 389 meshlets, submitted 30720 of 30720 triangles"
         "the CPU culls 174 for that view \\(127 outside the frustum, 47 facing away\\)")
# Culling changes the work, not the picture: without it every meshlet is
# drawn (all 30,720 triangles) and the picture is the same; so is chapter
# 15's way, one indirect draw of the whole model through a vertex shader.
vkt_chapter_test(chapter.26_mesh_shaders.no_culling 26_mesh_shaders SAME_AS chapter.26_mesh_shaders ${VKT_26_PIXEL}
  ARGS ${headless} --cull off
  EXPECT "culled 0 of 389 meshlets \\(0 outside the frustum, 0 facing away\\), drew 389 meshlets, submitted 30720 of 30720 triangles")
# The vertex pipeline's picture is compared within a tight tolerance, not to
# the bit: llvmpipe's vertex and mesh stages may round a clip-space position
# apart in the last bit (at --frames 2 one pixel differs by one level here),
# and which pixels that touches depends on the processor llvmpipe compiles for.
vkt_chapter_test(chapter.26_mesh_shaders.indirect 26_mesh_shaders ${VKT_26_PIXEL}
  ARGS ${headless} --draw indirect
  EXPECT "one vkCmdDrawIndexedIndirect \\(vertex shader\\)" "submitted 30720 triangles \\(the whole model\\)")
vkt_compare_pictures(chapter.26_mesh_shaders.indirect_agrees
  chapter.26_mesh_shaders chapter.26_mesh_shaders.indirect
  AGREE TOLERANCE 0.05,1,0.0002)
# The gaze turned 30 degrees left: the right part of the knot leaves the
# frustum. Turned 180 degrees: everything lies behind the camera.
vkt_chapter_test(chapter.26_mesh_shaders.turn_30 26_mesh_shaders ${VKT_26_PIXEL}
  ARGS ${headless} --turn 30
  EXPECT "culled 174 of 389 meshlets \\(127 outside the frustum, 47 facing away\\), drew 215 meshlets, submitted 17932 of 30720 triangles"
         "the CPU culls 174 for that view \\(127 outside the frustum, 47 facing away\\)")
# There, where the task shader culls 174 meshlets, drawing all 389 must give
# the same picture to the bit: no culled meshlet had a visible pixel.
vkt_chapter_test(chapter.26_mesh_shaders.turn_30_no_culling 26_mesh_shaders
  SAME_AS chapter.26_mesh_shaders.turn_30 ARGS ${headless} --turn 30 --cull off
  EXPECT "culled 0 of 389 meshlets")
# Turned 180 degrees, nothing is drawn: the whole picture is the clear colour,
# the centre and the corners included.
vkt_chapter_test(chapter.26_mesh_shaders.turn_180 26_mesh_shaders
  PIXEL 0,0,196,206,218,1 319,0,196,206,218,1 0,239,196,206,218,1 319,239,196,206,218,1
        160,120,196,206,218,1
  ARGS ${headless} --turn 180
  EXPECT "culled 389 of 389 meshlets \\(389 outside the frustum, 0 facing away\\), drew 0 meshlets, submitted 0 of 30720 triangles"
         "the CPU culls 389 for that view \\(389 outside the frustum, 0 facing away\\)")
# Any glTF: chapter 10's scene (five meshes in a node tree) as one mesh.
vkt_chapter_test(chapter.26_mesh_shaders.other_model 26_mesh_shaders ${VKT_26_PIXEL}
  ARGS ${headless} --model ${PROJECT_SOURCE_DIR}/assets/gltf/scene.gltf
  EXPECT "scene.gltf: 1056 triangles, 631 vertices -> 32 meshlets"
         "the last frame culled 12 of 32 meshlets" "the CPU culls 12 for that view")
# There too, drawing every meshlet gives the same picture to the bit.
vkt_chapter_test(chapter.26_mesh_shaders.other_model_no_culling 26_mesh_shaders
  SAME_AS chapter.26_mesh_shaders.other_model
  ARGS ${headless} --model ${PROJECT_SOURCE_DIR}/assets/gltf/scene.gltf --cull off
  EXPECT "culled 0 of 32 meshlets")
# The knot made finer by its own script (book/perf_26_mesh_shaders.md's dense
# case at 1,966,080 triangles; here 960 rings of 96, 184,320 triangles: past
# 65,535 vertices, so 32-bit indices). Its normals spread less per meshlet, so
# the cone test culls more; the three draws still give one picture.
find_package(Python3 COMPONENTS Interpreter QUIET)  # required (tests/CMakeLists.txt says so)
set(vkt_26_fine ${CMAKE_CURRENT_BINARY_DIR}/knot_960x96.glb)
add_test(NAME chapter.26_mesh_shaders.fine_knot.make
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make_knot_model.py
          --rings 960 --sides 96 --out ${vkt_26_fine})
set_tests_properties(chapter.26_mesh_shaders.fine_knot.make PROPERTIES
  FIXTURES_SETUP vkt_26_fine LABELS chapter)
vkt_chapter_test(chapter.26_mesh_shaders.fine_knot 26_mesh_shaders ${VKT_26_PIXEL}
  ARGS ${headless} --model ${vkt_26_fine}
  EXPECT "knot_960x96.glb: 184320 triangles, 93217 vertices -> [0-9]+ meshlets"
         "submitted [0-9]+ of 184320 triangles" "the CPU culls")
vkt_chapter_test(chapter.26_mesh_shaders.fine_knot_no_culling 26_mesh_shaders
  SAME_AS chapter.26_mesh_shaders.fine_knot ARGS ${headless} --model ${vkt_26_fine} --cull off
  EXPECT "culled 0 of [0-9]+ meshlets .*, submitted 184320 of 184320 triangles")
# The indirect draw within a tight tolerance, not to the bit: llvmpipe's
# vertex and mesh stages round clip-space positions differently in the last
# bits (chapter 28's path_task_agrees says more), and among these small
# triangles 2 of the 76,800 pixels come out one level apart in one channel.
vkt_chapter_test(chapter.26_mesh_shaders.fine_knot_indirect 26_mesh_shaders ${VKT_26_PIXEL}
  ARGS ${headless} --model ${vkt_26_fine} --draw indirect
  EXPECT "submitted 184320 triangles \\(the whole model\\)")
vkt_compare_pictures(chapter.26_mesh_shaders.fine_knot_indirect_agrees
  chapter.26_mesh_shaders.fine_knot chapter.26_mesh_shaders.fine_knot_indirect
  AGREE TOLERANCE 0.05,1,0.0002)
set_property(TEST chapter.26_mesh_shaders.fine_knot chapter.26_mesh_shaders.fine_knot_no_culling
  chapter.26_mesh_shaders.fine_knot_indirect APPEND PROPERTY FIXTURES_REQUIRED vkt_26_fine)
# The default knot is still the stored one, byte for byte; and a bad count
# is refused with a message and exit status 1.
add_test(NAME chapter.26_mesh_shaders.knot_model_unchanged
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make_knot_model.py --check)
add_test(NAME bad_input.26_mesh_shaders.knot_model_rings
  COMMAND sh -c "\"$0\" \"$1\" --rings 2 --out /dev/null 2>&1; echo \"exit $?\""
          ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make_knot_model.py)
set_tests_properties(chapter.26_mesh_shaders.knot_model_unchanged
  bad_input.26_mesh_shaders.knot_model_rings PROPERTIES LABELS chapter)
set_tests_properties(bad_input.26_mesh_shaders.knot_model_rings PROPERTIES
  PASS_REGULAR_EXPRESSION "make_knot_model.py: --rings wants a whole number from 3 to 4096, not '2'\nexit 1")
# The triangle and vertex counts above, checked against the files' own
# accessor counts (tests/chapters/gltf_counts.py reads only the JSON, walks
# the node tree, counts a mesh once per node using it), and the meshlet count
# against the bounds any builder with 64 vertices and 124 triangles must
# keep. A stand-in chapter that miscounts by one triangle is refused.
find_package(Python3 COMPONENTS Interpreter QUIET)  # required (tests/CMakeLists.txt says so)
add_test(NAME chapter.26_mesh_shaders.counts_match_gltf
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/chapters/gltf_counts.py
          $<TARGET_FILE:26_mesh_shaders> ${PROJECT_SOURCE_DIR}/assets/gltf/knot.glb
          ${PROJECT_SOURCE_DIR}/assets/gltf/scene.gltf ${PROJECT_SOURCE_DIR}/assets/gltf/scene.glb
          ${PROJECT_SOURCE_DIR}/assets/gltf/pbr_cubes.gltf)
set_tests_properties(chapter.26_mesh_shaders.counts_match_gltf PROPERTIES
  ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}"
  LABELS chapter
  PASS_REGULAR_EXPRESSION "pbr_cubes.gltf: the JSON says 24 triangles, 48 vertices .*; the chapter says 24, 48, ")
add_test(NAME chapter.26_mesh_shaders.counts_can_fail
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/chapters/gltf_counts.py
          ${CMAKE_CURRENT_SOURCE_DIR}/chapters/gltf_counts_wrong.sh
          ${PROJECT_SOURCE_DIR}/assets/gltf/scene.gltf)
set_tests_properties(chapter.26_mesh_shaders.counts_can_fail PROPERTIES LABELS chapter
  PASS_REGULAR_EXPRESSION "scene.gltf: the chapter's counts differ from the file's")
# --benchmark reports the "draw" scope.
vkt_chapter_test(chapter.26_mesh_shaders.benchmark 26_mesh_shaders
  ARGS --headless --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark
  EXPECT "\"gpu_scopes_ms\": \\{\"draw\": \\{\"min\": [0-9.]+, \"median\": [0-9.]+, \"p95\": [0-9.]+")
vkt_chapter_test(chapter.26_mesh_shaders.help 26_mesh_shaders EXIT 0 ARGS --help
  EXPECT "usage: 26_mesh_shaders" "--draw mesh\\|indirect" "--view lit\\|meshlets\\|culled"
         "--cull on\\|off" "--turn DEGREES" "--model FILE")

# Bad input: the command line (exit 2).
vkt_chapter_test(bad_input.26_mesh_shaders.draw 26_mesh_shaders EXIT 2 ARGS --draw vertex
  EXPECT "--draw wants one of mesh, indirect, not 'vertex'")
vkt_chapter_test(bad_input.26_mesh_shaders.view 26_mesh_shaders EXIT 2 ARGS --view normals
  EXPECT "--view wants one of lit, meshlets, culled, not 'normals'")
vkt_chapter_test(bad_input.26_mesh_shaders.cull 26_mesh_shaders EXIT 2 ARGS --cull maybe
  EXPECT "--cull wants one of on, off, not 'maybe'")
vkt_chapter_test(bad_input.26_mesh_shaders.turn 26_mesh_shaders EXIT 2 ARGS --turn 181
  EXPECT "--turn wants a number from -180 to 180, not '181'")
vkt_chapter_test(bad_input.26_mesh_shaders.meshlets_indirect 26_mesh_shaders EXIT 2
  ARGS --draw indirect --view meshlets EXPECT "--view meshlets needs --draw mesh")
# --view culled shows the task shader's verdicts: it needs the task shader
# (--draw mesh) and its tests (--cull on).
vkt_chapter_test(bad_input.26_mesh_shaders.culled_indirect 26_mesh_shaders EXIT 2
  ARGS --draw indirect --view culled
  EXPECT "--view culled needs --draw mesh: the indirect draw has no meshlets")
vkt_chapter_test(bad_input.26_mesh_shaders.culled_no_cull 26_mesh_shaders EXIT 2
  ARGS --cull off --view culled
  EXPECT "--view culled shows what the task shader's tests cull: it needs --cull on")
# Bad input: a model that is missing or not glTF (exit 1, one line).
vkt_chapter_test(bad_input.26_mesh_shaders.missing_model 26_mesh_shaders EXIT 1
  ARGS --headless --frames 1 --model ${CMAKE_CURRENT_BINARY_DIR}/no_such_model.glb
  EXPECT "no_such_model.glb")
vkt_chapter_test(bad_input.26_mesh_shaders.not_gltf 26_mesh_shaders EXIT 1
  ARGS --headless --frames 1 --model ${PROJECT_SOURCE_DIR}/assets/gltf/checker.png
  EXPECT "checker.png: ")
# A device without VK_EXT_mesh_shader (hidden: lavapipe has it): one clear
# line naming it, exit status 1.
vkt_chapter_test(bad_input.26_mesh_shaders.no_mesh_shader 26_mesh_shaders EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=VK_EXT_mesh_shader
  EXPECT "no Vulkan device can run this chapter; .* lacks the extension VK_EXT_mesh_shader \\(hidden by VKT_HIDE_FEATURES\\)")
# The extension offered but one of its two features not: said by name at
# device selection (vkt/core/extension_features.hpp), not left to
# vkCreateDevice's VK_ERROR_FEATURE_NOT_PRESENT.
foreach(missing taskShader meshShader)
  vkt_chapter_test(bad_input.26_mesh_shaders.no_${missing} 26_mesh_shaders EXIT 1
    ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=${missing}
    EXPECT "no Vulkan device can run this chapter; .* lacks the ${missing} feature of VK_EXT_mesh_shader \\(hidden by VKT_HIDE_FEATURES\\)")
endforeach()

# Issue 39's chain of 100,000 nodes (tests/make_hostile_files.cpp): loaded
# and drawn; one call per level overflowed the stack (chapter.10_gltf.node_chain).
vkt_chapter_test(chapter.26_mesh_shaders.node_chain 26_mesh_shaders
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE}
       --model ${VKT_HOSTILE_DIR}/node_chain.gltf
  EXPECT "node_chain.gltf: 1 triangles, 3 vertices -> 1 meshlets")
set_tests_properties(chapter.26_mesh_shaders.node_chain PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)

# Issue 39: triangles that share one vertex by the hundred thousand (files
# from tests/make_hostile_files.cpp). The builder's work is bounded per
# triangle (unit test "build_meshlets: work bounded per triangle ..."
# counts it); here the whole chapter must finish. Before, it rescanned every
# use of every meshlet vertex at each step and ran for minutes: the TIMEOUT
# is what failed then (each runs in about a second now).
vkt_chapter_test(chapter.26_mesh_shaders.fan_200000 26_mesh_shaders
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE}
       --model ${VKT_HOSTILE_DIR}/fan_200000.gltf
  EXPECT "fan_200000.gltf: 200000 triangles, 200002 vertices -> 3226 meshlets"
         "submitted 200000 of 200000 triangles")
vkt_chapter_test(chapter.26_mesh_shaders.zeros_100000 26_mesh_shaders
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE}
       --model ${VKT_HOSTILE_DIR}/zeros_100000.gltf
  EXPECT "zeros_100000.gltf: 100000 triangles, 1 vertices -> 807 meshlets")
set_tests_properties(chapter.26_mesh_shaders.fan_200000 chapter.26_mesh_shaders.zeros_100000
  PROPERTIES FIXTURES_REQUIRED vkt_hostile_files TIMEOUT 60)
# Instancing, charged: 2,000 nodes sharing a mesh of 300,000 vertices pass
# the loader's limit on vertices drawn (before: killed at 100 s with a peak
# of 21 GB, still flattening); 200 of them pass the budget once flattened
# (before: 11 s and a 5.7 GB peak, then refused for its task workgroups).
vkt_chapter_test(bad_input.26_mesh_shaders.instances_2000 26_mesh_shaders EXIT 1
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE}
       --model ${VKT_HOSTILE_DIR}/instances_2000.gltf
  EXPECT "26_mesh_shaders: error: .*instances_2000.gltf: node 224: mesh 0: drawn here too, it brings the vertices drawn to 67200000, past this loader's limit of 67108864")
vkt_chapter_test(bad_input.26_mesh_shaders.instances_200 26_mesh_shaders EXIT 1
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE}
       --model ${VKT_HOSTILE_DIR}/instances_200.gltf
  EXPECT "26_mesh_shaders: error: .*instances_200.gltf: its draws flattened into one mesh: needs 9155 MiB, which would bring what this file needs to [0-9]+ MiB, past the limit of 1 GiB \\(--max-memory\\)")
set_tests_properties(bad_input.26_mesh_shaders.instances_2000 bad_input.26_mesh_shaders.instances_200
  PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# A million empty materials (3 MB) with --max-memory 500M: tinygltf's objects
# for the root's arrays are charged before it parses (a Material is 2,144
# bytes in tinygltf 2.7). Before: exit 0 at a 2,412 MB peak (17.8 s).
vkt_chapter_test(bad_input.26_mesh_shaders.materials_1e6 26_mesh_shaders EXIT 1
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE}
       --model ${VKT_HOSTILE_DIR}/materials_1e6.gltf --max-memory 500M
  EXPECT "26_mesh_shaders: error: .*materials_1e6.gltf: its elements, as tinygltf's objects: needs [0-9]+ MiB, which would bring what this file needs to [0-9]+ MiB, past the limit of 500 MiB \\(--max-memory\\)")
set_tests_properties(bad_input.26_mesh_shaders.materials_1e6 PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
