# Chapter 11: a first-person camera walking round a courtyard; headless, a
# scripted path that depends on the frame's time only.
#
# Hand-worked pixels, frame 9 of 10, t = 9/60 = 0.15 s. The script
# (scripted_camera) puts the eye at angle 0.3 t = 0.045 round the middle:
# position (8 sin 0.045, 1.7, 8 cos 0.045) = (0.360, 1.7, 7.992), yaw
# -0.045 + 0.35 sin(0.06) = -0.0240, pitch -0.1 + 0.06 sin(0.135) = -0.0919,
# so forward = (cos p sin y, sin p, -cos p cos y) = (-0.0239, -0.0918, -0.9955).
# Every face is one flat colour, so a pixel well inside a face (3 pixels from
# any edge, checked) is exactly that colour, sRGB-encoded:
# - the top corners look 20 degrees above the horizon, over everything (the
#   walls reach 4 degrees, the nearest pillar top, the pink one's, 18): the
#   sky, the clear colour (0.25, 0.42, 0.72), stored (137, 173, 221);
# - (160, 120), the centre: the forward ray reaches z = 0.5, the white cube's
#   front face, after (7.992 - 0.5) / 0.9955 = 7.53 m, at x = 0.18, y = 1.01
#   (the face spans x -0.5..0.5, y 0.8..1.8): white 0.9 times the +z shade
#   0.9 = 0.81, stored (232, 232, 232);
# - (160, 200) and (160, 230), the floor in front: the rays through those
#   pixels' centres meet y = 0 at (0.29, 0, 4.57) in tile (0, 4), light
#   (0.55, 0.55, 0.52), stored (196, 196, 191), and at (0.30, 0, 5.40) in tile
#   (0, 5), dark (0.22, 0.23, 0.25), stored (129, 132, 137);
# - the red pillar (0.8, 0.15, 0.1) on the right, at (1.91, 0, 4.62): the eye
#   (x = 0.36) sees its -x face, shade 0.6, at (238, 100): (0.48, 0.09, 0.06),
#   stored (184, 85, 69), and its front, shade 0.9, at (250, 150):
#   (0.72, 0.135, 0.09), stored (221, 103, 85);
# - the pink pillar (0.85, 0.3, 0.55) on the left, its front at (30, 150):
#   (0.765, 0.27, 0.495), stored (227, 142, 187).
set(VKT_11_PIXEL PIXEL 0,0,137,173,221 319,0,137,173,221 160,120,232,232,232
                       160,200,196,196,191 160,230,129,132,137 238,100,184,85,69
                       250,150,221,103,85 30,150,227,142,187)
vkt_chapter_test(chapter.11_camera 11_camera GOLDEN BLESS ${VKT_11_PIXEL} ARGS ${headless})
vkt_chapter_test(chapter.11_camera.offscreen 11_camera SAME_AS chapter.11_camera ${VKT_11_PIXEL} ARGS ${offscreen})
# In a window with --frames the input is empty too: the same script, the same picture.
vkt_chapter_window_test(11_camera PIXEL 0,0,137,173,221 160,120,232,232,232 238,100,184,85,69)

# Input that only a window gives never reaches a headless run: many frames
# (most of a lap of the script), the default frame count, and one frame, all
# with validation, all clean.
vkt_chapter_test(chapter.11_camera.many_frames 11_camera
  ARGS --headless --validation --frames 400 --size 64x48)
vkt_chapter_test(chapter.11_camera.default_frames 11_camera
  ARGS --offscreen --validation --size 64x48)
vkt_chapter_test(chapter.11_camera.one_frame 11_camera
  ARGS --headless --validation --frames 1 --size 64x48 --speed 10 --sensitivity 0.01)

vkt_chapter_test(chapter.11_camera.help 11_camera EXIT 0 ARGS --help
  EXPECT "usage: 11_camera" "--speed M/S" "--sensitivity RAD")
vkt_chapter_test(bad_input.11_camera.speed_zero 11_camera EXIT 2 ARGS --speed 0
  EXPECT "--speed wants a number from 0.1 to 50, not '0'")
vkt_chapter_test(bad_input.11_camera.speed_text 11_camera EXIT 2 ARGS --speed fast
  EXPECT "--speed wants a number from 0.1 to 50, not 'fast'")
vkt_chapter_test(bad_input.11_camera.sensitivity_range 11_camera EXIT 2 ARGS --sensitivity 1
  EXPECT "--sensitivity wants a number from 0.0001 to 0.05, not '1'")

# In a real window, driven by events (window_camera.sh): W walks forward and
# the first Escape only releases the cursor, a click captures it again, the
# mouse moved right turns right, and only an Escape with the cursor free quits.
if(XVFB_RUN AND XDOTOOL AND OPENBOX)
  add_test(NAME chapter.11_camera.window_escape
    COMMAND ${XVFB_RUN} -a -s "-screen 0 800x600x24"
            ${CMAKE_CURRENT_SOURCE_DIR}/window_camera.sh $<TARGET_FILE:11_camera>
            ${VKT_TEST_OUTPUT} "11 - camera")
  set_tests_properties(chapter.11_camera.window_escape PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
endif()
