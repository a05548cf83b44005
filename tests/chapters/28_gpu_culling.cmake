# Chapter 28: GPU-driven culling (a compute pass culls instances into draw
# lists with a count, drawn by vkCmdDrawIndexedIndirectCount; two-phase
# occlusion culling against a depth pyramid).
#
# The tests draw 4,096 instances (a 64 x 64 field, 1.9 million triangles);
# the chapter's default, 100,000, is for the H200 (book/perf_28_gpu_culling.md).
#
# Two pixels worked out by hand. The sky is the clear colour, linear (0.55,
# 0.70, 0.90), stored sRGB-encoded as (196, 218, 243). The floor is linear
# grey 0.45 with normal +y: lambert = dot(+y, normalize(0.4, 1, 0.3)) =
# 1 / sqrt(1.25) = 0.8944, light 0.25 + 0.75 * 0.8944 = 0.9208, 0.45 * 0.9208
# = 0.4144, sRGB 172.3: stored 172 (within 1), in the bare floor at the
# bottom left.
set(VKT_28_ARGS --instances 4096)
set(VKT_28_PIXEL PIXEL 0,0,196,218,243 319,0,196,218,243 5,235,172,172,172,1)
# The counts after the last frame: the GPU's frustum count must equal the
# CPU's own (double-precision planes, scene.hpp; the chapter exits 1 when
# they disagree, and none lies on the boundary here). The occlusion numbers
# are the GPU's; the test asks that they add up.
set(VKT_28_COUNTS
  "last frame: ([0-9]+) of 4096 instances in the frustum \\(the CPU finds \\1, and 0 on its boundary\\)")
vkt_chapter_test(chapter.28_gpu_culling 28_gpu_culling GOLDEN BLESS ${VKT_28_PIXEL}
  ARGS ${headless} ${VKT_28_ARGS}
  EXPECT "4096 instances of 4 meshes \\(37 meshlets\\), 1935328 triangles; --cull occlusion, indirect draws"
         "${VKT_28_COUNTS}, [0-9]+ drawn \\([0-9]+ early \\+ [0-9]+ late\\), [1-9][0-9]* occluded")
vkt_chapter_test(chapter.28_gpu_culling.offscreen 28_gpu_culling SAME_AS chapter.28_gpu_culling
  ${VKT_28_PIXEL} ARGS ${offscreen} ${VKT_28_ARGS} EXPECT "${VKT_28_COUNTS}")
vkt_chapter_window_test(28_gpu_culling PIXEL 0,0,196,218,243 ARGS ${VKT_28_ARGS})

# A culled instance is truly invisible: drawing every instance, or those in
# the frustum, gives the picture occlusion culling gave, to the bit (same
# machine, same run). --cull none draws all 4,096; frustum exactly what the
# CPU counts in the frustum.
vkt_chapter_test(chapter.28_gpu_culling.cull_none 28_gpu_culling SAME_AS chapter.28_gpu_culling
  ${VKT_28_PIXEL} ARGS ${headless} ${VKT_28_ARGS} --cull none
  EXPECT "${VKT_28_COUNTS}, 4096 drawn \\(4096 early \\+ 0 late\\), 0 occluded")
vkt_chapter_test(chapter.28_gpu_culling.cull_frustum 28_gpu_culling
  SAME_AS chapter.28_gpu_culling ${VKT_28_PIXEL} ARGS ${headless} ${VKT_28_ARGS} --cull frustum
  EXPECT "last frame: ([0-9]+) of 4096 instances in the frustum \\(the CPU finds \\1, and 0 on its boundary\\), \\1 drawn \\(\\1 early \\+ 0 late\\), 0 occluded")
# The pyramid's min taken by the sampler (VK_SAMPLER_REDUCTION_MODE_MIN,
# which lavapipe offers) and by the shader: the same pyramid, the same culling.
vkt_chapter_test(chapter.28_gpu_culling.reduce_sampler 28_gpu_culling
  SAME_AS chapter.28_gpu_culling ARGS ${headless} ${VKT_28_ARGS} --reduce sampler
  EXPECT "takes the min in the sampler \\(VK_SAMPLER_REDUCTION_MODE_MIN\\)" "${VKT_28_COUNTS}")
vkt_chapter_test(chapter.28_gpu_culling.reduce_shader 28_gpu_culling
  SAME_AS chapter.28_gpu_culling ARGS ${headless} ${VKT_28_ARGS} --reduce shader
  EXPECT "takes the min in the shader \\(four texel fetches\\)" "${VKT_28_COUNTS}")
# A field of one instance (a wall) and of 5 (not a square): nothing breaks.
foreach(n 1 5)
  vkt_chapter_test(chapter.28_gpu_culling.instances_${n} 28_gpu_culling PIXEL 0,0,196,218,243
    ARGS ${headless} --instances ${n}
    EXPECT "last frame: ([0-9]+) of ${n} instances in the frustum \\(the CPU finds \\1")
endforeach()

# The debug views, each against its own golden (LABELS bless). The pyramid:
# level 1, a texel the farthest depth over 4 x 4 pixels (at level 3 a blocky picture
# shifted by one pixel passed the golden tolerance); the sky is depth
# 0 (reversed: the far plane), black. The culled: the occluded instances in
# one flat red (1, 0.05, 0.02), stored sRGB-encoded as (255, 63, 39), over
# the picture with no depth test; flat, so that where two overlap the order
# the cull appended them in (an atomic counter's) cannot change a pixel.
# (188, 103) is inside a hidden instance seen through a wall.
vkt_chapter_test(chapter.28_gpu_culling.view_pyramid 28_gpu_culling
  GOLDEN_FILE 28_gpu_culling_pyramid.png LABELS bless PIXEL 0,0,0,0,0 319,0,0,0,0
  ARGS ${headless} ${VKT_28_ARGS} --view pyramid --level 1 EXPECT "${VKT_28_COUNTS}")
vkt_chapter_test(chapter.28_gpu_culling.view_culled 28_gpu_culling
  GOLDEN_FILE 28_gpu_culling_culled.png LABELS bless PIXEL 0,0,196,218,243 188,103,255,63,39
  ARGS ${headless} ${VKT_28_ARGS} --view culled EXPECT "[1-9][0-9]* occluded")

# --path task: chapter 26's task and mesh shaders draw the same field, a
# task workgroup making the cull pass's test for 32 instances. The counts are
# the cull pass's. The picture is not the indirect path's to the bit on
# lavapipe: the triangles are the same, placed by the same GLSL function,
# but llvmpipe's vertex and mesh stages round the clip-space positions
# differently in the last bits (drawn as depth, 98 pixels differ by one
# part in 10^5), and 3 of the 76,800 pixels come out one level apart in one
# channel (RMSE 0.004). (On the H200 the two pictures are identical.) So
# the two are compared within a tight tolerance: RMSE at most 0.05 and no
# pixel more than 1 level off, beyond 0.02% of them (15).
set(VKT_28_TASK_TOLERANCE 0.05,1,0.0002)
# --meshlet-cull is on unless given: the task shader tests each meshlet of
# a kept instance and launches only the survivors. In this view some must
# face away: every sphere, cylinder and torus drawn shows the eye only its
# near side, and the meshlets of its far side have normal cones that point
# away (the cone test is conservative: it culls nothing that faces the eye,
# so the picture below is still the indirect path's).
vkt_chapter_test(chapter.28_gpu_culling.path_task 28_gpu_culling ${VKT_28_PIXEL}
  ARGS ${headless} ${VKT_28_ARGS} --path task
  EXPECT "--cull occlusion, task and mesh shaders"
         "${VKT_28_COUNTS}, [0-9]+ drawn \\([0-9]+ early \\+ [0-9]+ late\\), [1-9][0-9]* occluded"
         "--meshlet-cull on: [0-9]+ meshlets of the drawn instances, [0-9]+ launched; [1-9][0-9]* culled: [0-9]+ outside the frustum, [1-9][0-9]* facing away, [0-9]+ occluded")
# --meshlet-cull off launches every meshlet of every kept instance, and the
# picture is the same to the bit: a culled meshlet drew nothing.
vkt_chapter_test(chapter.28_gpu_culling.path_task_meshlet_cull_off 28_gpu_culling
  SAME_AS chapter.28_gpu_culling.path_task ARGS ${headless} ${VKT_28_ARGS} --path task
  --meshlet-cull off
  EXPECT "--meshlet-cull off: ([0-9]+) meshlets of the drawn instances, \\1 launched; 0 culled: 0 outside the frustum, 0 facing away, 0 occluded")
vkt_compare_pictures(chapter.28_gpu_culling.path_task_agrees
  chapter.28_gpu_culling chapter.28_gpu_culling.path_task
  AGREE TOLERANCE ${VKT_28_TASK_TOLERANCE})
# The tolerance refuses a picture that is nearly right: the task path one
# frame later (the camera turned by a hundredth of a degree; 0.6% of the
# pixels, at the edges, differ).
vkt_chapter_test(chapter.28_gpu_culling.path_task_frame_11 28_gpu_culling PIXEL 0,0,196,218,243
  ARGS --headless --validation --frames 11 --size ${VKT_TEST_SIZE} ${VKT_28_ARGS} --path task
  EXPECT "${VKT_28_COUNTS}")
vkt_compare_pictures(chapter.28_gpu_culling.path_task_tolerance_refuses
  chapter.28_gpu_culling chapter.28_gpu_culling.path_task_frame_11
  DIFFER TOLERANCE ${VKT_28_TASK_TOLERANCE})
# Within the task path, culling is invisible to the bit, as in the indirect.
vkt_chapter_test(chapter.28_gpu_culling.path_task_cull_none 28_gpu_culling
  SAME_AS chapter.28_gpu_culling.path_task ARGS ${headless} ${VKT_28_ARGS} --path task --cull none
  EXPECT "${VKT_28_COUNTS}, 4096 drawn \\(4096 early \\+ 0 late\\), 0 occluded")
# A device without VK_EXT_mesh_shader (hidden: lavapipe has it): --path task
# is refused in one line naming it, exit status 1; the indirect path runs.
vkt_chapter_test(bad_input.28_gpu_culling.path_task_no_mesh_shader 28_gpu_culling EXIT 1
  ARGS --headless --frames 1 --instances 64 --path task ENV VKT_HIDE_FEATURES=VK_EXT_mesh_shader
  EXPECT "no Vulkan device can run this chapter; .* lacks the extension VK_EXT_mesh_shader \\(hidden by VKT_HIDE_FEATURES\\)")
vkt_chapter_test(chapter.28_gpu_culling.indirect_without_mesh_shader 28_gpu_culling
  ARGS --headless --frames 1 --instances 64 ENV VKT_HIDE_FEATURES=VK_EXT_mesh_shader
  EXPECT "64 instances of 4 meshes .*indirect draws")

# --path task --view culled: after the frame, one more pass from a camera
# 40 m ahead of the tested one, 8 m right and 22 m up, looking back, launches
# every meshlet of every instance and colours each by what the tests made
# for the tested camera find: launched, lit as ever; outside the frustum
# (0.75, 0.05, 0.85), stored (225, 63, 237); facing away (1, 0.75, 0),
# (255, 225, 0); occluded, page 28's red (255, 63, 39). Flat colours,
# depth-tested: no pixel depends on the order of the launches. (40, 57) is
# on the floor's instances left of the frustum, (130, 186) on the back of a
# wall, (275, 201) an instance hidden behind that wall.
vkt_chapter_test(chapter.28_gpu_culling.path_task_view_culled 28_gpu_culling
  GOLDEN_FILE 28_gpu_culling_task_culled.png LABELS bless
  PIXEL 0,0,196,218,243 40,57,225,63,237 130,186,255,225,0 275,201,255,63,39
  ARGS ${headless} ${VKT_28_ARGS} --path task --view culled
  EXPECT "${VKT_28_COUNTS}"
         "--meshlet-cull on: [0-9]+ meshlets of the drawn instances, [0-9]+ launched; [1-9][0-9]* culled: [1-9][0-9]* outside the frustum, [1-9][0-9]* facing away, [1-9][0-9]* occluded")

# --benchmark: the GPU's scopes of the two phases.
vkt_chapter_test(chapter.28_gpu_culling.benchmark 28_gpu_culling
  ARGS --headless --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark ${VKT_28_ARGS}
  EXPECT "\"gpu_scopes_ms\": \\{\"cull 1\": \\{\"min\": [0-9.]+, \"median\": [0-9.]+"
         "\"pyramid\": \\{" "\"cull 2\": \\{" "\"draw 2\": \\{")
vkt_chapter_test(chapter.28_gpu_culling.help 28_gpu_culling EXIT 0 ARGS --help
  EXPECT "usage: 28_gpu_culling" "--instances N" "--cull" "--view" "--level L" "--path" "--reduce"
         "--meshlet-cull")

# Bad input: the command line (exit 2).
vkt_chapter_test(bad_input.28_gpu_culling.instances_zero 28_gpu_culling EXIT 2
  ARGS --instances 0 EXPECT "--instances wants a whole number from 1 to 1000000, not '0'")
vkt_chapter_test(bad_input.28_gpu_culling.instances_too_many 28_gpu_culling EXIT 2
  ARGS --instances 1000001 EXPECT "--instances wants a whole number from 1 to 1000000, not '1000001'")
vkt_chapter_test(bad_input.28_gpu_culling.cull 28_gpu_culling EXIT 2 ARGS --cull some
  EXPECT "--cull wants one of none, frustum, occlusion, not 'some'")
vkt_chapter_test(bad_input.28_gpu_culling.view 28_gpu_culling EXIT 2 ARGS --view depth
  EXPECT "--view wants one of shaded, pyramid, culled, not 'depth'")
vkt_chapter_test(bad_input.28_gpu_culling.reduce 28_gpu_culling EXIT 2 ARGS --reduce max
  EXPECT "--reduce wants one of auto, sampler, shader, not 'max'")
vkt_chapter_test(bad_input.28_gpu_culling.path 28_gpu_culling EXIT 2 ARGS --path mesh
  EXPECT "--path wants one of indirect, task, not 'mesh'")
vkt_chapter_test(bad_input.28_gpu_culling.view_culled_meshlet_cull_off 28_gpu_culling EXIT 2
  ARGS --view culled --path task --meshlet-cull off
  EXPECT "--view culled with --path task shows what the meshlet tests cull: it needs --meshlet-cull on")
vkt_chapter_test(bad_input.28_gpu_culling.meshlet_cull_without_task 28_gpu_culling EXIT 2
  ARGS --meshlet-cull on
  EXPECT "--meshlet-cull needs --path task: the indirect path draws whole instances, one command each, and has no meshlets")
vkt_chapter_test(bad_input.28_gpu_culling.meshlet_cull 28_gpu_culling EXIT 2
  ARGS --path task --meshlet-cull some EXPECT "--meshlet-cull wants one of on, off, not 'some'")
vkt_chapter_test(bad_input.28_gpu_culling.level 28_gpu_culling EXIT 2 ARGS --level 16
  EXPECT "--level wants a whole number from 0 to 15, not '16'")
vkt_chapter_test(bad_input.28_gpu_culling.view_culled_without_occlusion 28_gpu_culling EXIT 2
  ARGS --view culled --cull frustum
  EXPECT "--view culled needs --cull occlusion: only it builds a pyramid and occludes instances")
vkt_chapter_test(bad_input.28_gpu_culling.view_pyramid_without_occlusion 28_gpu_culling EXIT 2
  ARGS --view pyramid --cull none EXPECT "--view pyramid needs --cull occlusion")
