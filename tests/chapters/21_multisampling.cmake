# Chapter 21: a wheel of thin spokes and two quads that cut through each
# other, drawn with 4 samples per pixel (the default) and resolved.
#
# Hand-worked pixels: the corners are background, the clear colour (0.02,
# 0.02, 0.04) stored sRGB-encoded as (39, 39, 56).
set(VKT_21_PIXEL PIXEL 0,0,39,39,56 319,239,39,39,56)
# The edges, by pixel: a 50x40 rectangle left of the wheel's hub (x 10..59,
# y 100..139 at 320x240) holds only spokes, (1.0, 0.92, 0.7) stored as
# (255, 246, 218), and background. With one sample per pixel each pixel is
# one or the other; resolved from 4 samples, the pixels the spokes' edges
# cross take values between the two. How many, worked out from the geometry
# (the twelve quads of build_scene, the wheel's turn at frame 9, 0.175 rad,
# clip_from_world at 320x240, and Vulkan's standard 4x sample positions
# (0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)): 113 pixels
# have one to three of their four samples inside a spoke (110 all four, 1,777
# none: python3 tests/chapters/21_edge_pixels.py); lavapipe counts 114. The
# tests allow 10% either way (102 to 124).
set(VKT_21_SPOKES 10,100,50,40,39,39,56,255,246,218)
set(VKT_21_SPOKE_EDGES 102,124)
vkt_chapter_test(chapter.21_multisampling 21_multisampling GOLDEN BLESS ${VKT_21_PIXEL}
  BETWEEN ${VKT_21_SPOKES},${VKT_21_SPOKE_EDGES} ARGS ${headless}
  EXPECT "21_multisampling: 4x samples \\(the device offers [0-9, ]*4[0-9, ]*\\), sample shading off. multisampled colour and depth [0-9.]+ MiB, transient, (not )?lazily allocated")
vkt_chapter_test(chapter.21_multisampling.offscreen 21_multisampling SAME_AS chapter.21_multisampling ${VKT_21_PIXEL}
  BETWEEN ${VKT_21_SPOKES},${VKT_21_SPOKE_EDGES} ARGS ${offscreen})
vkt_chapter_window_test(21_multisampling PIXEL 0,0,39,39,56)
# The check can fail: at 1x, asking for blended edge pixels names the count.
vkt_chapter_test(chapter_check.between_can_fail 21_multisampling EXIT 0
  BETWEEN ${VKT_21_SPOKES},1,2000 ARGS ${headless} --samples 1)
set_tests_properties(chapter_check.between_can_fail PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: --between .*: 0 pixels lie between the two colours, expected 1 to 2000")

# Sample shading: the striped quad's stripes are decided in the fragment
# shader. Inside it (a 35x40 rectangle, x 250..284, y 90..129) multisampling
# alone leaves every pixel light (89, 225, 231) or dark (44, 120, 124): the
# shader ran once per pixel. With --sample-shading 1 it runs per sample and
# most pixels blend: worked out from the shader's formula at the four
# standard sample positions, 672 of the 1,400 have one to three light
# samples (lavapipe: 672); the test allows 10% either way (605 to 739).
set(VKT_21_STRIPES 250,90,35,40,89,225,231,44,120,124)
vkt_chapter_test(chapter.21_multisampling.stripes_alias 21_multisampling
  BETWEEN ${VKT_21_STRIPES},0,0 ARGS ${headless})
# The 1x and sample-shading pictures have goldens of their own: the book's
# zoomed comparison (book/diagrams/21_zoom.py) is drawn from these and the
# default. scripts/bless-goldens.sh 21_multisampling re-blesses all three.
vkt_chapter_test(chapter.21_multisampling.one_sample 21_multisampling
  GOLDEN_FILE 21_multisampling_1x.png LABELS bless ${VKT_21_PIXEL}
  BETWEEN ${VKT_21_SPOKES},0,0 ARGS ${headless} --samples 1
  EXPECT "21_multisampling: 1x samples .*sample shading off. depth [0-9.]+ MiB")
vkt_chapter_test(chapter.21_multisampling.sample_shading 21_multisampling
  GOLDEN_FILE 21_multisampling_sample_shading.png LABELS bless ${VKT_21_PIXEL}
  BETWEEN ${VKT_21_SPOKES},${VKT_21_SPOKE_EDGES} ${VKT_21_STRIPES},605,739
  ARGS ${headless} --sample-shading 1 EXPECT "4x samples .*sample shading on")
vkt_chapter_test(chapter.21_multisampling.help 21_multisampling EXIT 0 ARGS --help
  EXPECT "usage: 21_multisampling" "--samples N" "--sample-shading FRACTION" "--overlay on\\|off")

# The overlay (page 21b) in a headless run: --overlay on draws the panel, and
# --screenshot reads the presented image with it. At 640x480, where its text
# is legible, after 3 frames (Dear ImGui hides a new panel for its first
# frame, while it measures it). Hand-worked pixels, from the colours of Dear
# ImGui's dark style (StyleColorsDark), which reach the vertices as sRGB bytes:
# - the focused title bar, TitleBgActive (0.16, 0.29, 0.48), the bytes
#   (41, 74, 122): decoded by overlay.vert, encoded again by the _SRGB
#   target, stored as (41, 74, 122). Without the decode: (112, 147, 184).
# - the panel's background over the clear colour: WindowBg's 0.06 is the
#   byte 15, linear 0.00478, at the runner's alpha 0.85 (the byte 217) over
#   the clear colour (0.02, 0.02, 0.04) as the target stored it: the bytes
#   (39, 39, 56), linear (0.02029, 0.02029, 0.03955). The blend is linear
#   (0.00709, 0.00709, 0.00996), stored as (20, 20, 25); within 1. (Blending
#   over the unstored 0.04 would give blue 25.505, the byte 26.) Blending the
#   bytes undecoded would give (65, 65, 67).
set(VKT_21_PANEL PIXEL 300,18,41,74,122 300,60,20,20,25)
vkt_chapter_test(chapter.21_multisampling.overlay 21_multisampling
  GOLDEN_FILE 21_multisampling_overlay.png LABELS bless ${VKT_21_PANEL}
  ARGS --headless --validation --frames 3 --size 640x480 --overlay on
  EXPECT "overlay: 'Samples: 4' at [0-9]+,[0-9]+ [0-9]+x[0-9]+")
# Offscreen (our own image, no swapchain), the same picture to the bit.
vkt_chapter_test(chapter.21_multisampling.overlay_offscreen 21_multisampling
  SAME_AS chapter.21_multisampling.overlay ${VKT_21_PANEL}
  ARGS --offscreen --validation --frames 3 --size 640x480 --overlay on)
# The panel is really there: at the tests' size, the picture with it must be
# refused as the picture without it (the default golden run's), naming it.
vkt_chapter_test(chapter.21_multisampling.overlay_differs 21_multisampling
  SAME_AS chapter.21_multisampling ARGS ${headless} --overlay on)
set_tests_properties(chapter.21_multisampling.overlay_differs PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*chapter\\.21_multisampling\\.png")
# And --overlay off is the same picture as no flag, to the bit.
vkt_chapter_test(chapter.21_multisampling.overlay_off 21_multisampling
  SAME_AS chapter.21_multisampling ${VKT_21_PIXEL} ARGS ${headless} --overlay off)

# Bad input. A count the command line does not know: exit 2. A count the
# device does not offer (lavapipe offers 1 and 4): exit 1, naming the device
# and what it offers.
vkt_chapter_test(bad_input.21_multisampling.samples_3 21_multisampling EXIT 2 ARGS --samples 3
  EXPECT "--samples wants one of 1, 2, 4, 8, not '3'")
vkt_chapter_test(bad_input.21_multisampling.samples_64 21_multisampling EXIT 2 ARGS --samples 64
  EXPECT "--samples wants one of 1, 2, 4, 8, not '64'")
vkt_chapter_test(bad_input.21_multisampling.samples_8 21_multisampling EXIT 1
  ARGS --headless --frames 1 --samples 8
  EXPECT "21_multisampling: error: --samples 8: llvmpipe.* cannot render a colour and depth target with 8 samples per pixel \\(it offers 1, 4\\)")
vkt_chapter_test(bad_input.21_multisampling.samples_2 21_multisampling EXIT 1
  ARGS --headless --frames 1 --samples 2 EXPECT "--samples 2: .*\\(it offers 1, 4\\)")
# --overlay takes on or off, and only a chapter with an overlay takes it.
vkt_chapter_test(bad_input.21_multisampling.overlay_word 21_multisampling EXIT 2
  ARGS --overlay yes EXPECT "--overlay wants one of on, off, not 'yes'")
vkt_chapter_test(bad_input.21_multisampling.overlay_missing 21_multisampling EXIT 2
  ARGS --headless --overlay EXPECT "--overlay needs a value")
vkt_chapter_test(bad_input.21_multisampling.overlay_elsewhere 04_triangle EXIT 2
  ARGS --headless --overlay on EXPECT "--overlay is not used by this chapter: it has no settings panel")
vkt_chapter_test(bad_input.21_multisampling.sample_shading_range 21_multisampling EXIT 2
  ARGS --sample-shading 0.1 EXPECT "--sample-shading wants a number from 0.25 to 1, not '0.1'")
vkt_chapter_test(bad_input.21_multisampling.sample_shading_word 21_multisampling EXIT 2
  ARGS --sample-shading all EXPECT "--sample-shading wants a number")
vkt_chapter_test(bad_input.21_multisampling.sample_shading_one_sample 21_multisampling EXIT 2
  ARGS --samples 1 --sample-shading 1 EXPECT "--sample-shading needs --samples 2 or more")
vkt_chapter_test(bad_input.21_multisampling.no_sample_rate_shading 21_multisampling EXIT 1
  ARGS --headless --frames 1 --sample-shading 1 ENV VKT_HIDE_FEATURES=sampleRateShading
  EXPECT "--sample-shading: .* lacks the sampleRateShading feature \\(hidden by VKT_HIDE_FEATURES\\)")
# A size too large for the device, said so with the size: a 16384 x 16384
# target of 4 samples is 4 GiB, one byte past lavapipe's largest image
# (maxResourceSize), checked before the image is made (vkCreateImage would
# be a validation error). Before: "vkBindImageMemory failed with
# VK_ERROR_OUT_OF_DEVICE_MEMORY (-2) at memory.cpp:109", and no size.
vkt_chapter_test(bad_input.21_multisampling.size_too_large 21_multisampling EXIT 1
  ARGS --headless --validation --frames 1 --size 16384x16384
  EXPECT "21_multisampling: error: --size 16384x16384: too large for this device: an image of 16384x16384, 4 samples a pixel, needs 4 GiB \\(4294967296 bytes\\), and the device's largest (image of this format|allocation) is [0-9]+ bytes \\((maxResourceSize|maxMemoryAllocationSize)\\); try a smaller --size")
