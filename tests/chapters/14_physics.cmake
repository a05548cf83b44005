# Chapter 14: boxes that turn, falling into heaps, drawn with instancing.
#
# The picture is deterministic: headless, time is frame index / 60 and the
# physics runs exactly 2 fixed steps of 1/120 s per frame, and the same
# inputs give bit-equal physics (tests/unit/test_physics_world.cpp).
# --warmup 10 simulates 10 s (1200 steps) before the first frame: the heaps have
# settled and every box is asleep ("0 awake"), so frame 10 is a still picture
# of them, with the pyramid and the tower of --scene stacks beside them.
#
# Hand-worked pixels: the sky in the top corners is the clear colour, linear
# (0.30, 0.45, 0.65), stored sRGB-encoded as (149, 179, 211); the bare floor
# in the bottom corners is its grey 0x59 (linear 0.349, the instance colour
# is UNORM) lit from above: Lambert n . l = 1 / |(0.4, 1, 0.3)| = 0.894,
# ambient 0.25 + 0.75 x 0.894 = 0.921, so linear 0.321, stored (154, 154, 154).
#
# The tower, standing where it was built: the middle of the +x and +z faces of
# its boxes 4 and 16, projected through the chapter's camera, and the colour
# box_colour gives them lit by the shader's light (+x: 0.25 + 0.75 x 0.358,
# +z: 0.25 + 0.75 x 0.268), worked out from the scene, the camera and the
# shader alone by python3 tests/chapters/14_tower_pixels.py. Each lands in a
# 3x3 block of one colour; a tower that sank half a box, leaned or fell, or a
# face lit with the wrong normal, moves or changes them.
set(VKT_14_TOWER 40,94,61,133,133 37,94,57,125,125 30,46,146,130,58 26,46,137,121,54)
set(VKT_14_ARGS --warmup 10 --scene stacks)
set(VKT_14_PIXEL PIXEL 0,0,149,179,211 319,0,149,179,211 5,230,154,154,154 300,225,154,154,154
  ${VKT_14_TOWER})
vkt_chapter_test(chapter.14_physics 14_physics GOLDEN BLESS ${VKT_14_PIXEL} ARGS ${headless} ${VKT_14_ARGS}
  EXPECT "14_physics: 1000 boxes and the stacks, sort-and-sweep, 120 steps/s, 1200 warm-up steps, [0-9]+ contact points, 0 awake")
vkt_chapter_test(chapter.14_physics.offscreen 14_physics SAME_AS chapter.14_physics ARGS ${offscreen} ${VKT_14_ARGS})
vkt_chapter_window_test(14_physics ARGS ${VKT_14_ARGS})
# P, in a real window driven by events (window_physics_keys.sh): the chapter
# says it added the pyramid and the tower (75 boxes), a second P adds nothing,
# Escape quits with a clean validation report.
if(XVFB_RUN AND XDOTOOL AND OPENBOX)
  add_test(NAME chapter.14_physics.window_keys
    COMMAND ${XVFB_RUN} -a -s "-screen 0 800x600x24"
            ${CMAKE_CURRENT_SOURCE_DIR}/window_physics_keys.sh $<TARGET_FILE:14_physics>
            ${VKT_TEST_OUTPUT} "14 - Physics")
  set_tests_properties(chapter.14_physics.window_keys PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
endif()
# Brute force finds the same pairs in the same order, so the world, and the
# picture, are the same bit for bit.
vkt_chapter_test(chapter.14_physics.brute 14_physics SAME_AS chapter.14_physics ARGS ${headless} ${VKT_14_ARGS}
  --broadphase brute EXPECT "1000 boxes and the stacks, brute force")
vkt_chapter_test(chapter.14_physics.help 14_physics EXIT 0 ARGS --help
  EXPECT "usage: 14_physics" "--count N" "--broadphase sap\\|brute" "--warmup SECONDS"
         "--scene heaps\\|stacks")

# Bad input: no boxes, too many, a broad phase or scene it does not know.
vkt_chapter_test(bad_input.14_physics.count_zero 14_physics EXIT 2 ARGS --count 0
  EXPECT "--count wants a whole number from 1 to 65536, not '0'")
vkt_chapter_test(bad_input.14_physics.count_too_many 14_physics EXIT 2 ARGS --count 65537
  EXPECT "--count wants a whole number from 1 to 65536, not '65537'")
vkt_chapter_test(bad_input.14_physics.broadphase 14_physics EXIT 2 ARGS --broadphase grid
  EXPECT "--broadphase wants one of sap, brute, not 'grid'")
vkt_chapter_test(bad_input.14_physics.scene 14_physics EXIT 2 ARGS --scene tower
  EXPECT "--scene wants one of heaps, stacks, not 'tower'")
