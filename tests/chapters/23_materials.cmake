# Chapter 23: a grid of spheres, metallic 0 to 1 down and roughness 0.1 to 1
# across, shaded with glTF's metallic-roughness BRDF into an HDR target and
# tone mapped (ACES, Narkowicz's fit) into the _SRGB one.
#
# Hand-worked pixels: the corners show the sky, radiance (0.05, 0.06, 0.09)
# (chapters/23_materials/grid.hpp). Through the ACES fit at exposure 0 that
# is (0.0443, 0.0588, 0.1082), stored sRGB-encoded as (59, 69, 92). Clamped
# instead, at --exposure 2 (x4): (0.2, 0.24, 0.36), stored (124, 134, 162).
set(VKT_23_PIXEL PIXEL 0,0,59,69,92 319,239,59,69,92)
vkt_chapter_test(chapter.23_materials 23_materials GOLDEN BLESS ${VKT_23_PIXEL} ARGS ${headless}
  EXPECT "23_materials: the sphere grid, HDR target R16G16B16A16_SFLOAT, exposure \\+0.00 EV \\(x1.000\\), tone map ACES \\(Narkowicz's fit\\), bloom 0.00")
vkt_chapter_test(chapter.23_materials.offscreen 23_materials GOLDEN ${VKT_23_PIXEL} ARGS ${offscreen})
vkt_chapter_window_test(23_materials PIXEL 0,0,59,69,92)
vkt_chapter_test(chapter.23_materials.exposure 23_materials PIXEL 0,0,124,134,162
  ARGS ${headless} --exposure 2 --tone-map clamp EXPECT "exposure \\+2.00 EV \\(x4.000\\), tone map clamp")

# The CPU reference (common/scene/include/vkt/scene/pbr.hpp): at 60 points,
# three on each sphere, the HDR radiance the GPU wrote against the same BRDF,
# sky and lights evaluated on the CPU for the point of the exact sphere the
# pixel's centre sees: within 2% + 0.005 in every channel (lavapipe: the
# largest difference 70% of that).
vkt_chapter_test(chapter.23_materials.verify_cpu 23_materials ARGS ${headless} --verify cpu
  EXPECT "verify cpu: 60 points match the CPU reference")
# The white furnace: a white sphere (roughness 1, metallic 0) under a uniform
# sky of radiance 1 and no lights, its sky integrated by the same 64 fixed
# samples per lobe: every pixel where n.v >= 0.3 within 3% of 1 (lavapipe
# 0.972 to 0.979: single scattering loses a little). Clamped, the sky is
# white and the sphere (252 to 253) all but vanishes into it.
vkt_chapter_test(chapter.23_materials.furnace 23_materials GOLDEN_FILE 23_materials_furnace.png
  LABELS bless PIXEL 160,120,253,253,253,2 0,0,255,255,255
  ARGS ${headless} --scene furnace --tone-map clamp --verify furnace
  EXPECT "the white furnace" "verify furnace: [0-9]+ pixels from 0.9[7-9][0-9]+ to 1?[0-9.]+")

# Bloom: the HDR image halved into mip levels and added back up in compute,
# 30% of it mixed in; the spheres and their highlights glow. The HDR image
# itself is untouched: the CPU reference still holds.
vkt_chapter_test(chapter.23_materials.bloom 23_materials GOLDEN_FILE 23_materials_bloom.png
  LABELS bless ARGS ${headless} --bloom 0.3 --verify cpu
  EXPECT "bloom 0.30" "verify cpu: 60 points match the CPU reference")

# A glTF file with every texture: assets/gltf/pbr_cubes.gltf, two cubes of
# studs (normal map), polished metal studs on a rough dielectric checker
# (metallic-roughness), dark rings at their feet (occlusion) and a glowing
# ring on each face (emissive). The left cube has TANGENT, the right one not.
set(VKT_23_MODEL ${PROJECT_SOURCE_DIR}/assets/gltf/pbr_cubes.gltf)
vkt_chapter_test(chapter.23_materials.model 23_materials GOLDEN_FILE 23_materials_model.png
  LABELS bless PIXEL 0,0,59,69,92 ARGS ${headless} --model ${VKT_23_MODEL} EXPECT "a glTF model")

# What the loader does not support: an extension the file requires is refused
# by name (exit 1); one it only uses is a warning, and the rest is drawn.
set(vkt_23_dir ${CMAKE_CURRENT_BINARY_DIR}/23_materials)
file(READ ${VKT_23_MODEL} vkt_23_text)
string(REPLACE [=["scene": 0,]=]
  [=["extensionsUsed": ["KHR_texture_transform"], "extensionsRequired": ["KHR_texture_transform"], "scene": 0,]=]
  vkt_23_required "${vkt_23_text}")
file(WRITE ${vkt_23_dir}/texture_transform.gltf "${vkt_23_required}")
string(REPLACE [=["scene": 0,]=] [=["extensionsUsed": ["KHR_materials_clearcoat"], "scene": 0,]=]
  vkt_23_used "${vkt_23_text}")
file(WRITE ${vkt_23_dir}/clearcoat.gltf "${vkt_23_used}")
vkt_chapter_test(bad_input.23_materials.required_extension 23_materials EXIT 1
  ARGS ${headless} --model ${vkt_23_dir}/texture_transform.gltf
  EXPECT "texture_transform.gltf: requires extension KHR_texture_transform, which this loader does not support")
vkt_chapter_test(chapter.23_materials.unsupported_extension 23_materials
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE} --model ${vkt_23_dir}/clearcoat.gltf
  EXPECT "clearcoat.gltf: warning: uses extension KHR_materials_clearcoat, which this loader ignores")
vkt_chapter_test(bad_input.23_materials.missing_model 23_materials EXIT 1
  ARGS --headless --frames 1 --model ${vkt_23_dir}/no_such_file.gltf EXPECT "no_such_file.gltf")

vkt_chapter_test(chapter.23_materials.help 23_materials EXIT 0 ARGS --help
  EXPECT "usage: 23_materials" "--exposure EV" "--tone-map CURVE" "--scene SCENE" "--bloom F"
         "--model FILE" "--verify CHECK")

# Bad input: one clear line and exit status 2.
vkt_chapter_test(bad_input.23_materials.exposure_range 23_materials EXIT 2 ARGS --exposure 11
  EXPECT "--exposure wants a number from -10 to 10, not '11'")
vkt_chapter_test(bad_input.23_materials.exposure_word 23_materials EXIT 2 ARGS --exposure bright
  EXPECT "--exposure wants a number")
vkt_chapter_test(bad_input.23_materials.bloom_range 23_materials EXIT 2 ARGS --bloom 2
  EXPECT "--bloom wants a number from 0 to 1, not '2'")
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
  ARGS --verify all EXPECT "--verify wants one of cpu, furnace, not 'all'")
# A device without the depth layouts the chapter's depth barrier uses, or
# without maintenance4 (the bloom's LocalSizeId): exit 1, named.
vkt_chapter_test(bad_input.23_materials.no_separate_depth_stencil 23_materials EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=separateDepthStencilLayouts
  EXPECT "separateDepthStencilLayouts")
vkt_chapter_test(bad_input.23_materials.no_maintenance4 23_materials EXIT 1
  ARGS --headless --frames 1 ENV VKT_HIDE_FEATURES=maintenance4 EXPECT "maintenance4")

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
