# Chapter 23: a grid of spheres, metallic 0 to 1 down and roughness 0.1 to 1
# across, shaded with glTF's metallic-roughness BRDF into an HDR target and
# tone mapped (ACES, Narkowicz's fit) into the _SRGB one. Here under the
# environment (--sky environment; the default is the uniform sky, below): a
# sky made at start-up into a cube map, lit by image-based light (the split
# sum's three images, made in compute), and drawn behind the spheres.
#
# Hand-worked pixels of the background (shaders/23_materials/sky.comp): the
# top corners' view rays rise 0.310 (y of the unit ray through the pixel's
# centre, fov 40 degrees, 4:3), so the sky there is mix(horizon, zenith,
# sqrt(0.310)) = (0.1319, 0.1686, 0.2643), through ACES (0.1831, 0.2476,
# 0.3935), stored (119, 136, 168); the bottom corners' fall 0.310, past the
# blend into the ground, (0.035, 0.03, 0.025), through ACES (0.0252,
# 0.0198, 0.0148), stored (44, 38, 33). Within 2: the cube map's half floats
# and linear filtering (lavapipe: exact at the top, 39 for 38 at the bottom).
set(VKT_23_SKY_PIXEL PIXEL 0,0,119,136,168,2 319,0,119,136,168,2 0,239,44,38,33,2
  319,239,44,38,33,2)
vkt_chapter_test(chapter.23_materials 23_materials GOLDEN BLESS ${VKT_23_SKY_PIXEL}
  ARGS ${headless} --sky environment
  EXPECT "23_materials: the sphere grid, sky environment \\(image-based light\\), HDR target R16G16B16A16_SFLOAT, exposure \\+0.00 EV \\(x1.000\\), tone map ACES \\(Narkowicz's fit\\), bloom 0.00"
         "image-based light made in [0-9.]+ ms of GPU time \\(sky [0-9.]+, irradiance [0-9.]+, specular [0-9.]+, BRDF table [0-9.]+\\)")
vkt_chapter_test(chapter.23_materials.offscreen 23_materials SAME_AS chapter.23_materials ${VKT_23_SKY_PIXEL}
  ARGS ${offscreen} --sky environment)
vkt_chapter_window_test(23_materials PIXEL 0,0,119,136,168,2 ARGS --sky environment)

# The uniform sky, integrated per pixel: the default (page 23's), so this test
# leaves out --sky and expects "sky uniform". Hand-worked pixels:
# the corners show the sky, radiance (0.05, 0.06, 0.09)
# (chapters/23_materials/grid.hpp). Through the ACES fit at exposure 0 that
# is (0.0443, 0.0588, 0.1082), sRGB-encoded (59.4, 68.6, 92.50), stored
# (59, 69, 92) within 1 (lavapipe: 93, blue on the rounding point). Clamped
# instead, at --exposure 2 (x4): (0.2, 0.24, 0.36), stored (124, 134, 162).
set(VKT_23_PIXEL PIXEL 0,0,59,69,92 319,239,59,69,92)
vkt_chapter_test(chapter.23_materials.uniform 23_materials GOLDEN_FILE 23_materials_uniform.png
  LABELS bless ${VKT_23_PIXEL} ARGS ${headless} EXPECT "the sphere grid, sky uniform")
# The same grid cut at 1 instead of ACES (--tone-map clamp), for page 23b's
# side by side: the sky (0.05, 0.06, 0.09) sRGB-encoded as it is, (63.2,
# 69.3, 84.6), stored (63, 69, 85) within 1; its own golden image.
vkt_chapter_test(chapter.23_materials.clamp 23_materials GOLDEN_FILE 23_materials_clamp.png
  LABELS bless PIXEL 0,0,63,69,85,1 319,239,63,69,85,1 ARGS ${headless} --sky uniform --tone-map clamp
  EXPECT "exposure \\+0.00 EV \\(x1.000\\), tone map clamp")
vkt_chapter_test(chapter.23_materials.exposure 23_materials PIXEL 0,0,124,134,162
  ARGS ${headless} --sky uniform --exposure 2 --tone-map clamp
  EXPECT "exposure \\+2.00 EV \\(x4.000\\), tone map clamp")
# Page 23b's exposure strip: the uniform sky's grid through ACES at -2 and
# +2 EV (0 EV is chapter.23_materials.uniform), each its own golden image.
# Hand-worked sky pixels: (0.05, 0.06, 0.09) times 1/4 is (0.0125, 0.015,
# 0.0225), through ACES (0.0052, 0.0068, 0.0126), sRGB-encoded (16.03,
# 19.58, 29.44), stored (16, 20, 29) within 1 (lavapipe: blue 30); times 4
# it is (0.2, 0.24, 0.36), through ACES (0.2995, 0.3600, 0.5036),
# sRGB-encoded (148.78, 161.74, 188.13), stored (149, 162, 188) within 1
# (lavapipe: exact).
vkt_chapter_test(chapter.23_materials.exposure_minus_2 23_materials
  GOLDEN_FILE 23_materials_exposure_minus_2.png LABELS bless
  PIXEL 0,0,16,20,29,1 319,239,16,20,29,1 ARGS ${headless} --sky uniform --exposure -2
  EXPECT "exposure -2.00 EV \\(x0.250\\), tone map ACES")
vkt_chapter_test(chapter.23_materials.exposure_plus_2 23_materials
  GOLDEN_FILE 23_materials_exposure_plus_2.png LABELS bless
  PIXEL 0,0,149,162,188,1 319,239,149,162,188,1 ARGS ${headless} --sky uniform --exposure 2
  EXPECT "exposure \\+2.00 EV \\(x4.000\\), tone map ACES")
# Each against the picture at 0 EV must differ by more than rounding (RMSE
# above 0.2, or more than 0.1% of the pixels more than 2 levels apart): an
# exposure the tone-mapping pass never applied leaves the three alike.
foreach(ev minus_2 plus_2)
  vkt_compare_pictures(chapter.23_materials.exposure_${ev}_differs
    chapter.23_materials.uniform chapter.23_materials.exposure_${ev} DIFFER TOLERANCE 0.2,2,0.001)
endforeach()

# The CPU reference (common/scene/include/vkt/scene/pbr.hpp): at 60 points,
# three on each sphere, the HDR radiance the GPU wrote against the same BRDF,
# sky and lights evaluated on the CPU for the point of the exact sphere the
# pixel's centre sees: within 2% + 0.005 in every channel (lavapipe: the
# largest difference 70% of that).
vkt_chapter_test(chapter.23_materials.verify_cpu 23_materials ARGS ${headless} --sky uniform --verify cpu
  EXPECT "verify cpu: 60 points match the CPU reference")
# The white furnace: a white sphere (roughness 1, metallic 0) under a uniform
# sky of radiance 1 and no lights, its sky integrated by the same 64 fixed
# samples per lobe: every pixel where n.v >= 0.3 within 3% of 1 (lavapipe
# 0.972 to 0.979: single scattering loses a little). Clamped, the sky is
# white and the sphere (252 to 253) all but vanishes into it.
vkt_chapter_test(chapter.23_materials.furnace 23_materials GOLDEN_FILE 23_materials_furnace.png
  LABELS bless PIXEL 160,120,253,253,253,2 0,0,255,255,255
  ARGS ${headless} --scene furnace --sky uniform --tone-map clamp --verify furnace
  EXPECT "the white furnace" "verify furnace: [0-9]+ pixels from 0.9[7-9][0-9]+ to 1?[0-9.]+")
# The white furnace through the image-based light: the environment a cube
# map of radiance 1 everywhere, then the irradiance cube, the prefiltered
# specular cube and the BRDF table made from it as from any sky, the sphere
# shaded by the split sum. The diffuse part gets what the specular lobe did
# not reflect, so with irradiance and prefiltered sky both 1 the sphere is
# 1 - S + S = 1 and only rounding stands between it and 1: every pixel where
# n.v >= 0.3 within 0.5% (lavapipe 0.9995 to 1.0000). A convolution that
# lost its normalisation, a face written in one direction and read in
# another, or a mip level left empty moves it by far more.
set(vkt_23_near_1 "(0\\.99[5-9][0-9]|1\\.00[0-4][0-9])")
vkt_chapter_test(chapter.23_materials.furnace_environment 23_materials
  ARGS ${headless} --scene furnace --sky environment --tone-map clamp --verify furnace
  EXPECT "the white furnace, sky environment"
         "verify furnace: [0-9]+ pixels from ${vkt_23_near_1} to ${vkt_23_near_1}")
# The BRDF table the GPU made at start-up, read back, against the CPU's
# integration of the same formula (vkt::pbr::split_sum_lut) at nine (n.v,
# roughness) texels: with the same 1024 samples within 0.002 (lavapipe
# 0.0003: half floats), with 16 times as many within 0.02 (lavapipe 0.0102,
# at a grazing n.v of 0.11; with 256 samples it was 0.044 there).
vkt_chapter_test(chapter.23_materials.brdf_table 23_materials
  ARGS ${headless} --sky environment --verify lut
  EXPECT "verify lut: 9 points match the CPU integration, with the same samples within 0.002")

# Bloom: the HDR image halved into mip levels and added back up in compute,
# 30% of it mixed in; the spheres and their highlights glow. The HDR image
# itself is untouched: the CPU reference still holds.
vkt_chapter_test(chapter.23_materials.bloom 23_materials GOLDEN_FILE 23_materials_bloom.png
  LABELS bless ARGS ${headless} --sky uniform --bloom 0.3 --verify cpu
  EXPECT "bloom 0.30" "verify cpu: 60 points match the CPU reference")
# Karis's average in the first halving (--bloom-average karis): the two small
# highlights on the smooth gold sphere at the bottom left, which the plain
# mean spreads into bright squares of glow, keep only a faint one; its own
# golden image. Against the plain mean's golden image it must fail: a flag
# that changed nothing would pass there.
vkt_chapter_test(chapter.23_materials.bloom_karis 23_materials GOLDEN_FILE 23_materials_bloom_karis.png
  LABELS bless ARGS ${headless} --sky uniform --bloom 0.3 --bloom-average karis --verify cpu
  EXPECT "bloom 0.30, Karis average" "verify cpu: 60 points match the CPU reference")
vkt_chapter_test(chapter.23_materials.bloom_karis_differs 23_materials GOLDEN_FILE 23_materials_bloom.png
  ARGS ${headless} --sky uniform --bloom 0.3 --bloom-average karis)
set_tests_properties(chapter.23_materials.bloom_karis_differs PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*23_materials_bloom\\.png")

# --term d|f|v: one factor of the specular BRDF alone, as a number through
# the clamp curve (page 23's row of pictures; shaders/23_materials/scene.frag).
# Hand-worked for the ray through each pixel's centre (a sphere of radius
# 0.5 at grid.hpp's place; tone map clamp, exposure 0): (250, 51) on the top
# right sphere (roughness 1, metallic 0), (69, 51) on the top left
# (roughness 0.1, metallic 0), (69, 188) on the bottom left (roughness 0.1,
# gold). D at roughness 1 is 1/pi whatever n.h: 0.3183, sRGB-encoded 152.95,
# stored (153, 153, 153). At roughness 0.1, 36 degrees from the highlight,
# D is 0.0003: (1, 1, 1) within 1. F where n.v is 0.9997 is F0: the
# plastic's 0.04, (56, 56, 56); gold's (1, 0.71, 0.29), (255, 219.2, 146.6),
# stored (255, 219, 147) within 1 (lavapipe: 146). G on the polished sphere
# is 0.9997, (255, 255, 255); on the rough one, at n.l 0.55, 0.7136, stored
# (220, 220, 220) within 1 (219.7). The corners are the sky, cut at 1 as in
# chapter.23_materials.clamp.
set(vkt_23_term_sky 0,0,63,69,85,1 319,239,63,69,85,1)
vkt_chapter_test(chapter.23_materials.term_d 23_materials GOLDEN_FILE 23_materials_term_d.png
  LABELS bless PIXEL ${vkt_23_term_sky} 250,51,153,153,153,1 69,51,1,1,1,1
  ARGS ${headless} --sky uniform --tone-map clamp --term d)
vkt_chapter_test(chapter.23_materials.term_f 23_materials GOLDEN_FILE 23_materials_term_f.png
  LABELS bless PIXEL ${vkt_23_term_sky} 69,51,56,56,56,1 250,51,56,56,56,1 69,188,255,219,147,1
  ARGS ${headless} --sky uniform --tone-map clamp --term f)
vkt_chapter_test(chapter.23_materials.term_v 23_materials GOLDEN_FILE 23_materials_term_v.png
  LABELS bless PIXEL ${vkt_23_term_sky} 69,51,255,255,255,1 250,51,220,220,220,1
  ARGS ${headless} --sky uniform --tone-map clamp --term v)
# Each against the whole BRDF drawn with the same flags (chapter.23_materials.clamp's
# golden image) must fail: a --term that changed nothing would pass there.
foreach(term d f v)
  vkt_chapter_test(chapter.23_materials.term_${term}_differs 23_materials
    GOLDEN_FILE 23_materials_clamp.png ARGS ${headless} --sky uniform --tone-map clamp --term ${term})
  set_tests_properties(chapter.23_materials.term_${term}_differs PROPERTIES
    PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*23_materials_clamp\\.png")
endforeach()
vkt_chapter_test(bad_input.23_materials.term_word 23_materials EXIT 2 ARGS --term g
  EXPECT "--term wants one of all, d, f, v, not 'g'")
vkt_chapter_test(bad_input.23_materials.term_model 23_materials EXIT 2
  ARGS --model cubes.gltf --term d --sky uniform
  EXPECT "--term d shows the sphere grid's BRDF: leave out --model")
vkt_chapter_test(bad_input.23_materials.term_furnace 23_materials EXIT 2
  ARGS --scene furnace --term f --sky uniform
  EXPECT "--term f needs the grid's lights: leave out --scene furnace")
vkt_chapter_test(bad_input.23_materials.term_verify 23_materials EXIT 2
  ARGS --verify cpu --term v --sky uniform
  EXPECT "--verify cpu checks the whole BRDF: leave out --term v")
vkt_chapter_test(bad_input.23_materials.term_view 23_materials EXIT 2 ARGS --view brdf --term d
  EXPECT "--term d draws the spheres: leave out --view brdf")
vkt_chapter_test(bad_input.23_materials.term_environment 23_materials EXIT 2
  ARGS --term d --sky environment
  EXPECT "--term d is drawn by the uniform sky's shader: leave out --sky environment")

# A glTF file with every texture: assets/gltf/pbr_cubes.gltf, two cubes of
# studs (normal map), polished metal studs on a rough dielectric checker
# (metallic-roughness), dark rings at their feet (occlusion) and a glowing
# ring on each face (emissive). The left cube has TANGENT, the right one not.
set(VKT_23_MODEL ${PROJECT_SOURCE_DIR}/assets/gltf/pbr_cubes.gltf)
set(vkt_23_dir ${CMAKE_CURRENT_BINARY_DIR}/23_materials)
vkt_chapter_test(chapter.23_materials.model 23_materials GOLDEN_FILE 23_materials_model.png
  LABELS bless PIXEL 0,0,59,69,92 ARGS ${headless} --sky uniform --model ${VKT_23_MODEL}
  EXPECT "a glTF model")
# The stored file is what its script makes, byte for byte.
find_package(Python3 COMPONENTS Interpreter QUIET)  # required (tests/CMakeLists.txt says so)
add_test(NAME chapter.23_materials.cubes_model_unchanged
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make_pbr_cubes.py --check)
set_tests_properties(chapter.23_materials.cubes_model_unchanged PROPERTIES LABELS chapter)
add_test(NAME bad_input.23_materials.cubes_single_word
  COMMAND sh -c "\"$0\" \"$1\" --single both /dev/null 2>&1; echo \"exit $?\""
          ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make_pbr_cubes.py)
set_tests_properties(bad_input.23_materials.cubes_single_word PROPERTIES LABELS chapter
  PASS_REGULAR_EXPRESSION "make_pbr_cubes.py: --single wants one of tangent, made, not 'both'\nexit 1")
# The frame the shader makes against the file's TANGENT: one cube alone, the
# same turn, once with TANGENT and once without (make_pbr_cubes.py --single),
# drawn by the same camera. The two frames are the same on every face, so
# the pictures must agree but for rounding (lavapipe: 4 of the 76,800 pixels
# one level apart in one channel, RMSE 0.004): RMSE at most 0.05, no pixel
# more than 1 level off beyond 0.02% of them. A made frame turned half round
# (the shader without det's sign: Vulkan's window y runs down) lights the
# studs from the wrong side: RMSE 11.3, 8.2% of the pixels more than 1 off.
set(vkt_23_tangent ${vkt_23_dir}/cube_tangent.gltf)
set(vkt_23_made ${vkt_23_dir}/cube_made.gltf)
add_test(NAME chapter.23_materials.single_cube.make
  COMMAND sh -c "\"$0\" \"$1\" --single tangent \"$2\" && \"$0\" \"$1\" --single made \"$3\""
          ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make_pbr_cubes.py
          ${vkt_23_tangent} ${vkt_23_made})
set_tests_properties(chapter.23_materials.single_cube.make PROPERTIES
  FIXTURES_SETUP vkt_23_single_cube LABELS chapter)
vkt_chapter_test(chapter.23_materials.cube_tangent 23_materials GOLDEN_FILE 23_materials_cube.png
  LABELS bless PIXEL 0,0,59,69,92 ARGS ${headless} --sky uniform --model ${vkt_23_tangent}
  EXPECT "a glTF model")
vkt_chapter_test(chapter.23_materials.cube_made 23_materials PIXEL 0,0,59,69,92
  ARGS ${headless} --sky uniform --model ${vkt_23_made} EXPECT "a glTF model")
set_property(TEST chapter.23_materials.cube_tangent chapter.23_materials.cube_made
  APPEND PROPERTY FIXTURES_REQUIRED vkt_23_single_cube)
vkt_compare_pictures(chapter.23_materials.made_frame_agrees
  chapter.23_materials.cube_tangent chapter.23_materials.cube_made
  AGREE TOLERANCE 0.05,1,0.0002)

# Page 23e's maps switched on in turn: the same single cube (TANGENT) with
# only the first N of its five maps (make_pbr_cubes.py --maps N): 1 base
# colour; 2 + metallic-roughness; 3 + normal; 4 + occlusion; 5, all five, is
# cube_tangent above. A map left out is drawn with glTF 2.0's defaults (the
# loader's factors, the chapter's white and flat stand-in textures): without
# metallic-roughness the cube is rough metal (metallic 1, roughness 1).
# Each step has its golden image, and each must differ from the step before
# by more than rounding: RMSE above 0.2, or more than 0.1% of the pixels more
# than 2 levels apart. A map the loader dropped or the shader ignored leaves
# two steps alike (RMSE 0), and the step's "differs" test fails. The smallest
# step, occlusion (it dims the sky's light only), is RMSE 0.63 with 2.3% of
# the pixels more than 2 levels apart on lavapipe; the golden tolerance alone
# would tell it from step 3 by the bias only (0.13, the limit 0.08).
set(vkt_23_maps 1_base 2_metal_rough 3_normal 4_occlusion)
set(vkt_23_map_files)
foreach(step IN LISTS vkt_23_maps)
  list(APPEND vkt_23_map_files ${vkt_23_dir}/cube_maps_${step}.gltf)
endforeach()
add_test(NAME chapter.23_materials.maps.make
  COMMAND sh -c "p=$0 s=$1 n=1; shift; for out; do \"$p\" \"$s\" --maps $n \"$out\" || exit 1; n=$((n + 1)); done"
          ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make_pbr_cubes.py ${vkt_23_map_files})
set_tests_properties(chapter.23_materials.maps.make PROPERTIES
  FIXTURES_SETUP vkt_23_maps LABELS chapter)
set(vkt_23_previous)
foreach(step IN LISTS vkt_23_maps ITEMS 5)
  if(step STREQUAL "5")
    set(vkt_23_test chapter.23_materials.cube_tangent)
  else()
    set(vkt_23_test chapter.23_materials.maps_${step})
    vkt_chapter_test(${vkt_23_test} 23_materials GOLDEN_FILE 23_materials_maps_${step}.png
      LABELS bless PIXEL 0,0,59,69,92
      ARGS ${headless} --sky uniform --model ${vkt_23_dir}/cube_maps_${step}.gltf EXPECT "a glTF model")
    set_property(TEST ${vkt_23_test} APPEND PROPERTY FIXTURES_REQUIRED vkt_23_maps)
  endif()
  if(vkt_23_previous)
    string(SUBSTRING ${step} 0 1 n)
    vkt_compare_pictures(chapter.23_materials.maps_${n}_differs ${vkt_23_previous} ${vkt_23_test}
      DIFFER TOLERANCE 0.2,2,0.001)
  endif()
  set(vkt_23_previous ${vkt_23_test})
endforeach()
add_test(NAME bad_input.23_materials.cubes_maps_count
  COMMAND sh -c "\"$0\" \"$1\" --maps 6 /dev/null 2>&1; echo \"exit $?\""
          ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/scripts/make_pbr_cubes.py)
set_tests_properties(bad_input.23_materials.cubes_maps_count PROPERTIES LABELS chapter
  PASS_REGULAR_EXPRESSION "make_pbr_cubes.py: --maps wants a number from 1 to 5, not '6'\nexit 1")

# What the loader does not support: an extension the file requires is refused
# by name (exit 1); one it only uses is a warning, and the rest is drawn.
file(READ ${VKT_23_MODEL} vkt_23_text)
string(REPLACE [=["scene": 0,]=]
  [=["extensionsUsed": ["KHR_texture_transform"], "extensionsRequired": ["KHR_texture_transform"], "scene": 0,]=]
  vkt_23_required "${vkt_23_text}")
file(WRITE ${vkt_23_dir}/texture_transform.gltf "${vkt_23_required}")
string(REPLACE [=["scene": 0,]=] [=["extensionsUsed": ["KHR_materials_clearcoat"], "scene": 0,]=]
  vkt_23_used "${vkt_23_text}")
file(WRITE ${vkt_23_dir}/clearcoat.gltf "${vkt_23_used}")
vkt_chapter_test(bad_input.23_materials.required_extension 23_materials EXIT 1
  ARGS ${headless} --sky environment --model ${vkt_23_dir}/texture_transform.gltf
  EXPECT "texture_transform.gltf: requires extension KHR_texture_transform, which this loader does not support")
vkt_chapter_test(chapter.23_materials.unsupported_extension 23_materials
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE} --sky environment
       --model ${vkt_23_dir}/clearcoat.gltf
  EXPECT "clearcoat.gltf: warning: uses extension KHR_materials_clearcoat, which this loader ignores")
vkt_chapter_test(bad_input.23_materials.missing_model 23_materials EXIT 1
  ARGS --headless --frames 1 --sky environment --model ${vkt_23_dir}/no_such_file.gltf
  EXPECT "no_such_file.gltf")

vkt_chapter_test(chapter.23_materials.help 23_materials EXIT 0 ARGS --help
  EXPECT "usage: 23_materials" "--exposure EV" "--tone-map CURVE" "--scene SCENE" "--sky SKY" "--bloom F"
         "--bloom-average KIND" "--term TERM" "--model FILE" "--verify CHECK")

# Bad input: one clear line and exit status 2.
vkt_chapter_test(bad_input.23_materials.exposure_range 23_materials EXIT 2 ARGS --exposure 11
  EXPECT "--exposure wants a number from -10 to 10, not '11'")
vkt_chapter_test(bad_input.23_materials.exposure_word 23_materials EXIT 2 ARGS --exposure bright
  EXPECT "--exposure wants a number")
vkt_chapter_test(bad_input.23_materials.bloom_range 23_materials EXIT 2 ARGS --bloom 2
  EXPECT "--bloom wants a number from 0 to 1, not '2'")
vkt_chapter_test(bad_input.23_materials.bloom_average 23_materials EXIT 2 ARGS --bloom-average soft
  EXPECT "--bloom-average wants one of box, karis, not 'soft'")
vkt_chapter_test(bad_input.23_materials.bloom_average_without_bloom 23_materials EXIT 2
  ARGS --bloom-average karis EXPECT "--bloom-average karis changes the bloom: add --bloom F")
vkt_chapter_test(bad_input.23_materials.tone_map 23_materials EXIT 2 ARGS --tone-map reinhard
  EXPECT "--tone-map wants one of aces, clamp, not 'reinhard'")
vkt_chapter_test(bad_input.23_materials.scene 23_materials EXIT 2 ARGS --scene box
  EXPECT "--scene wants one of grid, furnace, not 'box'")
vkt_chapter_test(bad_input.23_materials.model_and_furnace 23_materials EXIT 2
  ARGS --model ${VKT_23_MODEL} --scene furnace EXPECT "--model draws a glTF file: leave out --scene furnace")
vkt_chapter_test(bad_input.23_materials.verify_model 23_materials EXIT 2
  ARGS --model ${VKT_23_MODEL} --verify cpu EXPECT "--verify checks the generated spheres: leave out --model")
vkt_chapter_test(bad_input.23_materials.verify_furnace 23_materials EXIT 2
  ARGS --verify furnace EXPECT "--verify furnace needs --scene furnace")
vkt_chapter_test(bad_input.23_materials.verify_word 23_materials EXIT 2
  ARGS --verify all EXPECT "--verify wants one of cpu, furnace, lut, not 'all'")
vkt_chapter_test(bad_input.23_materials.sky 23_materials EXIT 2 ARGS --sky cloudy
  EXPECT "--sky wants one of uniform, environment, not 'cloudy'")
vkt_chapter_test(bad_input.23_materials.verify_cpu_environment 23_materials EXIT 2
  ARGS --verify cpu --sky environment
  EXPECT "--verify cpu checks the uniform sky's CPU reference: leave out --sky environment")
vkt_chapter_test(bad_input.23_materials.verify_lut_uniform 23_materials EXIT 2 ARGS --verify lut
  EXPECT "--verify lut checks the environment's BRDF table: add --sky environment")
# A device without the depth layouts the chapter's depth barrier uses, or
# without maintenance4 (the bloom's LocalSizeId): exit 1, named.
vkt_chapter_test(bad_input.23_materials.no_separate_depth_stencil 23_materials EXIT 1
  ARGS --headless --frames 1 --sky environment ENV VKT_HIDE_FEATURES=separateDepthStencilLayouts
  EXPECT "separateDepthStencilLayouts")
vkt_chapter_test(bad_input.23_materials.no_maintenance4 23_materials EXIT 1
  ARGS --headless --frames 1 --sky environment ENV VKT_HIDE_FEATURES=maintenance4
  EXPECT "maintenance4")

# The overlay in a window: one click on "clamp" changes the tone curve live.
if(XVFB_RUN AND XDOTOOL AND OPENBOX AND TARGET imgui::imgui)
  add_test(NAME chapter.23_materials.window_overlay
    COMMAND ${XVFB_RUN} -a -s "-screen 0 800x600x24"
            ${PROJECT_SOURCE_DIR}/tests/window_overlay.sh $<TARGET_FILE:23_materials>
            ${VKT_TEST_OUTPUT} "23 - Physically based materials and HDR" "Tone map: clamp"
            "Tone map = clamp")
  set_tests_properties(chapter.23_materials.window_overlay PROPERTIES
    ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}" LABELS "chapter;window")
endif()

# Issue 39's chain of 100,000 nodes (tests/make_hostile_files.cpp): loaded
# and drawn; one call per level overflowed the stack (chapter.10_gltf.node_chain).
vkt_chapter_test(chapter.23_materials.node_chain 23_materials
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE} --sky environment
       --model ${VKT_HOSTILE_DIR}/node_chain.gltf
  EXPECT "a glTF model")
set_tests_properties(chapter.23_materials.node_chain PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# 65,156 materials, one descriptor set each: before, lavapipe aborted
# ("LLVM ERROR: Unable to allocate section memory", signal 6).
vkt_chapter_test(bad_input.23_materials.materials_65156 23_materials EXIT 1
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE} --sky environment
       --model ${VKT_HOSTILE_DIR}/materials_65156.gltf
  EXPECT "23_materials: error: .*materials_65156.gltf: materials: 65156 of them, past this loader's limit of 4096")
set_tests_properties(bad_input.23_materials.materials_65156 PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# A NaN normal (tests/make_hostile_files.cpp): before, exit 0 and lit black.
vkt_chapter_test(bad_input.23_materials.nan_normal 23_materials EXIT 1
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE} --sky environment
       --model ${VKT_HOSTILE_DIR}/nan_normal.gltf
  EXPECT "23_materials: error: .*nan_normal.gltf: mesh 0 primitive 0 NORMAL: accessor 1: element 2, component 2, is NaN, not a finite number")
set_tests_properties(bad_input.23_materials.nan_normal PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)

# The image-based light's images (--view), drawn in place of the scene into
# the HDR image and shown through the same exposure and ACES curve, at
# 640x480 so that the page can show them large. Hand-worked from sky.comp's
# formula, ACES (Narkowicz's fit) and the sRGB encoding: the background 0.02
# gives (26, 26, 26). The cubes' crosses have faces of 160 pixels from
# (0, 0): the +Y face's centre (240, 80) looks straight up, at the zenith
# (0.03, 0.08, 0.22), (38, 85, 156); the -Y face's centre (240, 400) at the
# ground (0.035, 0.03, 0.025), (44, 38, 33). The prefiltered cube's level 0
# is for roughness 0, the sky unblurred: its panorama (213 x 106 pixels from
# (0, 133)) at (106, 229) looks 72 degrees down, at the ground.
set(vkt_23_views --headless --validation --frames ${VKT_TEST_FRAMES} --size 640x480)
vkt_chapter_test(chapter.23_materials.view_sky 23_materials GOLDEN_FILE 23_materials_view_sky.png
  LABELS bless PIXEL 40,40,26,26,26 240,80,38,85,156,2 240,400,44,38,33,2
  ARGS ${vkt_23_views} --sky environment --view sky)
vkt_chapter_test(chapter.23_materials.view_irradiance 23_materials
  GOLDEN_FILE 23_materials_view_irradiance.png LABELS bless PIXEL 40,40,26,26,26
  ARGS ${vkt_23_views} --sky environment --view irradiance)
vkt_chapter_test(chapter.23_materials.view_prefiltered 23_materials
  GOLDEN_FILE 23_materials_view_prefiltered.png LABELS bless PIXEL 5,5,26,26,26 106,229,44,38,33,2
  ARGS ${vkt_23_views} --sky environment --view prefiltered)
# The BRDF table through the clamp curve, so red and green are its two
# numbers as stored: at n.v 0.98 and roughness 0.02 (the top right texel)
# the lobe is a mirror and Schlick's F is F0 + (1 - F0)(1 - n.v)^5, so A =
# 1 - (1 - n.v)^5 = 1 and B = (1 - n.v)^5 = 0 to 8 digits: (255, 0, 0). The
# background 0.02 unmapped: (39, 39, 39).
vkt_chapter_test(chapter.23_materials.view_brdf 23_materials
  GOLDEN_FILE 23_materials_view_brdf.png LABELS bless PIXEL 5,5,39,39,39 555,3,255,0,0,1
  ARGS ${vkt_23_views} --sky environment --view brdf --tone-map clamp)
vkt_chapter_test(bad_input.23_materials.view_uniform_sky 23_materials EXIT 2 ARGS --view sky
  EXPECT "--view sky shows the environment's images: add --sky environment")
vkt_chapter_test(bad_input.23_materials.view_verify 23_materials EXIT 2
  ARGS --view brdf --verify furnace --scene furnace --sky environment
  EXPECT "--verify furnace checks the scene: leave out --view brdf")

# --view bloom (page 23d): this frame's bloom chain, drawn over the scene once
# the bloom has read it, through the same exposure and ACES curve, at 640x480
# like the views above. Twelve panels of 160 by 120 pixels from (80, 0), three
# across: the way down's levels 0 to 5 (a copy made halfway), then the same
# levels after the way up. Hand-worked: the background 0.02 gives (26, 26,
# 26); the way down's levels 0 to 3 at their top left texel hold the mean of
# at most 24 by 24 of the scene's pixels in its top left corner, bare sky
# (0.05, 0.06, 0.09), stored (59, 69, 92) within 1, as chapter.23_materials.uniform.
# An empty copy (the copy or its barrier gone) leaves those panels black.
vkt_chapter_test(chapter.23_materials.view_bloom 23_materials
  GOLDEN_FILE 23_materials_view_bloom.png LABELS bless
  PIXEL 40,40,26,26,26 85,4,59,69,92,1 245,4,59,69,92,1 405,4,59,69,92,1 85,124,59,69,92,1
  ARGS ${vkt_23_views} --sky uniform --bloom 0.3 --view bloom)
# The same flags at 320x240 against the scene's golden image must fail: a view
# that drew nothing would leave the scene there.
vkt_chapter_test(chapter.23_materials.view_bloom_differs 23_materials GOLDEN_FILE 23_materials_bloom.png
  ARGS ${headless} --sky uniform --bloom 0.3 --view bloom)
set_tests_properties(chapter.23_materials.view_bloom_differs PROPERTIES
  PASS_REGULAR_EXPRESSION "FAIL: picture differs from .*23_materials_bloom\\.png")
vkt_chapter_test(bad_input.23_materials.view_bloom_without_bloom 23_materials EXIT 2
  ARGS --view bloom --sky uniform EXPECT "--view bloom shows the bloom's levels: add --bloom F")
vkt_chapter_test(bad_input.23_materials.view_bloom_verify 23_materials EXIT 2
  ARGS --view bloom --bloom 0.3 --sky uniform --verify cpu
  EXPECT "--verify cpu checks the scene: leave out --view bloom")
