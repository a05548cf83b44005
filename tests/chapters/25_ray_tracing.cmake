# Chapter 25: the ray-tracing pipeline. A mirror ball, three coloured shapes
# and a checkered floor that reflects a fifth of what it sees, under one
# directional light travelling along (0.7, -1, -0.25) / 1.246; the camera at
# (0, 2.4, 7) looks at (0, 0.8, 0), 45 degrees high. Every pixel is one ray
# (no noise, no accumulation), so the picture is the same after any number
# of frames and on any device, but for the last bit of rounding.
#
# Hand-worked pixels at 320x240 (the miss shader's sky is
# mix((0.75, 0.82, 0.9), (0.25, 0.45, 0.8), direction.y)):
#  - (0, 0): sky; the pixel's ray has y = 0.1477: (0.676, 0.765, 0.885),
#    stored sRGB-encoded as (214, 227, 242).
#  - (72, 168): the floor point (-1.88, 0, 1.15), straight down the light
#    from the red ball's centre (-2.3, 0.6, 1.3): in its shadow, a dark cell
#    (albedo 0.3 x (0.9, 0.9, 0.85)) lit by the ambient 0.15 alone,
#    (0.0405, 0.0405, 0.038); mixed 80/20 with its reflection, sky at
#    y = 0.364 (0.568, 0.685, 0.864): (0.146, 0.169, 0.203), stored
#    (107, 114, 124). With --bounces 0 no reflection: (57, 57, 55).
#  - (160, 112): the mirror ball's front, its normal about (0, 0.196, 0.981):
#    Lambert 0.354, so without reflections (--bounces 0) 0.95 x (0.15 + 0.85
#    x 0.354) = 0.428, stored 174 (the tessellated normal gives 173).
set(VKT_25_PIXEL PIXEL 0,0,214,227,242,2 72,168,107,114,124,2)
vkt_chapter_test(chapter.25_ray_tracing 25_ray_tracing GOLDEN BLESS ${VKT_25_PIXEL} ARGS ${headless}
  EXPECT "25_ray_tracing: 2 bounces, recursion depth 4 of [0-9]+"
  "shader binding table: handles 32 bytes, records 32 \\(handle alignment 16\\), tables at multiples of 32: ray generation at 0, miss at 32 \\(2 records\\), hit at 96 \\(1 record\\), 128 bytes")
vkt_chapter_test(chapter.25_ray_tracing.offscreen 25_ray_tracing SAME_AS chapter.25_ray_tracing ${VKT_25_PIXEL} ARGS ${offscreen})
# In a window the blit writes the swapchain's B8G8R8A8_SRGB image itself.
vkt_chapter_window_test(25_ray_tracing PIXEL 0,0,214,227,242,2 72,168,107,114,124,2)
# No reflections: the recursion is 2 deep (the camera's ray, the shadow
# ray), the mirror ball shows only its own shading, and the shadowed floor
# point loses its share of sky. Its own golden (LABELS bless).
vkt_chapter_test(chapter.25_ray_tracing.no_bounces 25_ray_tracing
  GOLDEN_FILE 25_ray_tracing_no_bounces.png LABELS bless
  PIXEL 0,0,214,227,242,2 72,168,57,57,55,2 160,112,174,174,174,3
  ARGS ${headless} --bounces 0 EXPECT "0 bounces, recursion depth 2 of")
# More bounces than lavapipe's maxRayRecursionDepth (31) allows: clamped to
# 29, the deepest reflection's shadow ray at depth 31.
vkt_chapter_test(chapter.25_ray_tracing.clamped 25_ray_tracing PIXEL 0,0,214,227,242,2
  ARGS --headless --validation --frames 1 --size 160x120 --bounces 40
  EXPECT "29 bounces, recursion depth 31 of 31 \\(--bounces clamped to the device's limit\\)")
vkt_chapter_test(chapter.25_ray_tracing.help 25_ray_tracing EXIT 0 ARGS --help
  EXPECT "usage: 25_ray_tracing" "--bounces N")

# A device without the ray-tracing pipeline (lavapipe has it; the test hides
# it): one clear line naming the extension, exit 1.
vkt_chapter_test(bad_input.25_ray_tracing.no_pipeline 25_ray_tracing EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=VK_KHR_ray_tracing_pipeline
  EXPECT "lacks the extension VK_KHR_ray_tracing_pipeline \\(hidden by VKT_HIDE_FEATURES\\)")
vkt_chapter_test(bad_input.25_ray_tracing.no_pipeline_feature 25_ray_tracing EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=rayTracingPipeline
  EXPECT "lacks the rayTracingPipeline feature of VK_KHR_ray_tracing_pipeline \\(hidden by VKT_HIDE_FEATURES\\)")
vkt_chapter_test(bad_input.25_ray_tracing.no_structures 25_ray_tracing EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=VK_KHR_acceleration_structure
  EXPECT "lacks the extension VK_KHR_acceleration_structure \\(hidden by VKT_HIDE_FEATURES\\)")
# A device whose rays may not recurse (maxRayRecursionDepth 1, the least
# the specification allows): no shadow rays from a hit shader, exit 1.
vkt_chapter_test(bad_input.25_ray_tracing.no_recursion 25_ray_tracing EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=maxRayRecursionDepth
  EXPECT "needs maxRayRecursionDepth 2; the device allows 1")
# Bad values: one clear line and exit status 2.
vkt_chapter_test(bad_input.25_ray_tracing.negative_bounces 25_ray_tracing EXIT 2
  ARGS --bounces -1 EXPECT "--bounces wants a whole number from 0 to 64, not '-1'")
vkt_chapter_test(bad_input.25_ray_tracing.too_many_bounces 25_ray_tracing EXIT 2
  ARGS --bounces 65 EXPECT "--bounces wants a whole number from 0 to 64")
vkt_chapter_test(bad_input.25_ray_tracing.bad_bounces 25_ray_tracing EXIT 2
  ARGS --bounces many EXPECT "--bounces wants a whole number from 0 to 64, not 'many'")
