# Chapter 10: a glTF scene (assets/gltf/scene.gltf), framed from its bounding
# box and orbiting slowly.
#
# Hand-worked pixels: the top corners show the clear colour (0.02, 0.02, 0.04),
# stored sRGB-encoded as (39, 39, 56); the scene never reaches them, because
# the camera keeps the whole bounding sphere inside the narrower field of view.
set(VKT_10_PIXEL PIXEL 0,0,39,39,56 319,0,39,39,56)
vkt_chapter_test(chapter.10_gltf 10_gltf GOLDEN BLESS ${VKT_10_PIXEL} ARGS ${headless}
  EXPECT "10_gltf: .*scene.gltf: draws 5, primitives 5, materials 5, images 3")
vkt_chapter_test(chapter.10_gltf.offscreen 10_gltf SAME_AS chapter.10_gltf ${VKT_10_PIXEL} ARGS ${offscreen})
vkt_chapter_window_test(10_gltf PIXEL 0,0,39,39,56)
# The same scene as one .glb (JSON chunk, BIN chunk, images in bufferViews)
# must give the same picture.
vkt_chapter_test(chapter.10_gltf.glb 10_gltf SAME_AS chapter.10_gltf ${VKT_10_PIXEL}
  ARGS ${headless} --model ${PROJECT_SOURCE_DIR}/assets/gltf/scene.glb
  EXPECT "10_gltf: .*scene.glb: draws 5, primitives 5, materials 5, images 3")
vkt_chapter_test(chapter.10_gltf.help 10_gltf EXIT 0 ARGS --help
  EXPECT "usage: 10_gltf" "--model FILE")

# --- Bad input: small files written here, each wrong in one way -------------
# A triangle, (0,0,0) (1,0,0) (0,1,0), with 16-bit indices, in a data: URI;
# @INDICES@, @COUNT@ and @EXTRA@ make it wrong.
set(vkt_10_dir ${CMAKE_CURRENT_BINARY_DIR}/gltf_bad_input)
set(vkt_10_good_indices "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA=")
set(vkt_10_template [=[{
  "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0, 1]}}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": @COUNT@, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,@INDICES@"}]@EXTRA@
}]=])
function(vkt_10_bad_file name indices count extra)
  string(REPLACE "@INDICES@" "${indices}" text "${vkt_10_template}")
  string(REPLACE "@COUNT@" "${count}" text "${text}")
  string(REPLACE "@EXTRA@" "${extra}" text "${text}")
  file(WRITE ${vkt_10_dir}/${name} "${text}")
endfunction()
vkt_10_bad_file(good.gltf ${vkt_10_good_indices} 3 "")
vkt_10_bad_file(long_accessor.gltf ${vkt_10_good_indices} 4 "")
vkt_10_bad_file(index_past_end.gltf
  "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAcAAAA=" 3 "")
vkt_10_bad_file(draco.gltf ${vkt_10_good_indices} 3
  [=[, "extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"]]=])
vkt_10_bad_file(warnings.gltf ${vkt_10_good_indices} 3
  [=[, "extensionsUsed": ["KHR_materials_emissive_strength"], "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]]=])
file(WRITE ${vkt_10_dir}/not_gltf.gltf "This is a text file, not glTF.\n")
# An image whose bytes are "this is not a PNG".
string(REPLACE [=["materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0, 1]}}],]=]
  [=["materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}],
  "textures": [{"source": 0}], "images": [{"uri": "data:image/png;base64,dGhpcyBpcyBub3QgYSBQTkc="}],]=]
  vkt_10_bad_image "${vkt_10_template}")
string(REPLACE "@INDICES@" "${vkt_10_good_indices}" vkt_10_bad_image "${vkt_10_bad_image}")
string(REPLACE "@COUNT@" "3" vkt_10_bad_image "${vkt_10_bad_image}")
string(REPLACE "@EXTRA@" "" vkt_10_bad_image "${vkt_10_bad_image}")
file(WRITE ${vkt_10_dir}/bad_image.gltf "${vkt_10_bad_image}")

set(vkt_10_run --headless --validation --frames 1 --size ${VKT_TEST_SIZE})
# The template itself is fine: one orange triangle. Worked by hand: it has
# no normals, so it is flat shaded with its face normal, +z for the
# counter-clockwise (0,0,0) (1,0,0) (0,1,0), facing the camera; the fixed sun
# normalize(0.4, 1, 0.7) gives cos = 0.7 / 1.2845 = 0.5450, light
# 0.25 + 0.75 x 0.5450 = 0.6587, so the base colour (1, 0.5, 0) becomes
# linear (0.6587, 0.3294, 0), stored sRGB-encoded as (212, 155, 0); the
# background is the clear colour (39, 39, 56).
vkt_chapter_test(chapter.10_gltf.small_file 10_gltf ARGS ${vkt_10_run} --model ${vkt_10_dir}/good.gltf
  PIXEL 140,130,212,155,0 0,0,39,39,56 300,30,39,39,56
  EXPECT "good.gltf: draws 1, primitives 1, materials 1, images 0, vertices 3, indices 3")
vkt_chapter_test(bad_input.10_gltf.missing_model 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/no-such-model.gltf
  EXPECT "10_gltf: error: cannot open .*no-such-model.gltf")
vkt_chapter_test(bad_input.10_gltf.not_gltf 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/not_gltf.gltf
  EXPECT "10_gltf: error: .*not_gltf.gltf: not a glTF file: ")
vkt_chapter_test(bad_input.10_gltf.broken_accessor 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/long_accessor.gltf
  EXPECT "long_accessor.gltf: mesh 0 primitive 0 POSITION: accessor 0 \\(count 4, byteOffset 0, stride 12\\) runs past the end of bufferView 0 \\(36 bytes\\)")
vkt_chapter_test(bad_input.10_gltf.index_past_end 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/index_past_end.gltf
  EXPECT "index_past_end.gltf: mesh 0 primitive 0: index 2 is 7, past the end of the vertex data \\(3 vertices\\)")
vkt_chapter_test(bad_input.10_gltf.bad_image 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/bad_image.gltf
  EXPECT "bad_image.gltf: image 0: cannot decode image: ")
vkt_chapter_test(bad_input.10_gltf.required_extension 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/draco.gltf
  EXPECT "draco.gltf: requires extension KHR_draco_mesh_compression, which this loader does not support")
# What is only ignored is a warning, and the rest is drawn.
vkt_chapter_test(chapter.10_gltf.warnings 10_gltf ARGS ${vkt_10_run} --model ${vkt_10_dir}/warnings.gltf
  EXPECT "warnings.gltf: warning: uses extension KHR_materials_emissive_strength, which this loader ignores"
         "warnings.gltf: warning: cameras are ignored"
         "warnings.gltf: draws 1, primitives 1")

# --- Files: only inside the model's folder, only regular files, 1 GiB at most
# (common/scene/src/gltf_files.cpp, through tinygltf's FsCallbacks of our own).
# Each is one line naming the model and what it named.
# vkt_10_uri_file(<name> <buffer uri> <extra>): the good triangle, its buffer at <uri>.
function(vkt_10_uri_file name uri extra)
  string(REPLACE "data:application/octet-stream;base64,@INDICES@" "${uri}" text "${vkt_10_template}")
  string(REPLACE "@COUNT@" "3" text "${text}")
  string(REPLACE "@EXTRA@" "${extra}" text "${text}")
  file(WRITE ${vkt_10_dir}/${name} "${text}")
endfunction()
vkt_10_uri_file(uri_outside.gltf "../../../../../../etc/passwd" "")
vkt_10_uri_file(uri_absolute.gltf "/etc/passwd" "")
vkt_10_uri_file(huge_buffer.gltf "huge.bin" "")
# tinygltf's issue 416: "%!Q" %-decodes to a NUL byte, and tinygltf alone then
# reads the folder as a file of 2^63 bytes (std::bad_alloc, or an ASan abort).
vkt_10_bad_file(issue416.gltf ${vkt_10_good_indices} 3 [=[, "images": [{"uri": "%!QAAAQAAA5"}]]=])
# A URI of "." names the model's folder itself; data: URIs whose base64 does
# not decode (tinygltf's own words for these name no buffer or image).
vkt_10_uri_file(uri_dot.gltf "." "")
vkt_10_bad_file(short_data_uri.gltf "AAA" 3 "")
vkt_10_bad_file(bad_image_data_uri.gltf ${vkt_10_good_indices} 3
  [=[, "images": [{"uri": "data:image/png;base64,!!"}]]=])

vkt_chapter_test(bad_input.10_gltf.model_directory 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}
  EXPECT "10_gltf: error: .*gltf_bad_input: is a directory, not a file")
vkt_chapter_test(bad_input.10_gltf.issue416_uri 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/issue416.gltf
  EXPECT "10_gltf: error: .*issue416.gltf: image 0: URI \"%00AAAQAAA5\" is not a file name: it holds a control character")
vkt_chapter_test(bad_input.10_gltf.uri_dot 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/uri_dot.gltf
  EXPECT "10_gltf: error: .*uri_dot.gltf: buffer 0: URI \"\\.\": .*gltf_bad_input: is a directory, not a file")
vkt_chapter_test(bad_input.10_gltf.short_data_uri 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/short_data_uri.gltf
  EXPECT "10_gltf: error: .*short_data_uri.gltf: buffer 0: data URI \"data:application/octet-stream;base64,AAA\" is invalid: its base64 decodes to 2 bytes, not the buffer's byteLength 44")
vkt_chapter_test(bad_input.10_gltf.bad_image_data_uri 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/bad_image_data_uri.gltf
  EXPECT "10_gltf: error: .*bad_image_data_uri.gltf: image 0: its data URI is invalid: its base64 decodes to no bytes")
vkt_chapter_test(bad_input.10_gltf.uri_outside 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/uri_outside.gltf
  EXPECT "10_gltf: error: .*uri_outside.gltf: buffer 0: URI \"\\.\\./\\.\\./\\.\\./\\.\\./\\.\\./\\.\\./etc/passwd\" leads out of the model's folder")
vkt_chapter_test(bad_input.10_gltf.uri_absolute 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${vkt_10_dir}/uri_absolute.gltf
  EXPECT "10_gltf: error: .*uri_absolute.gltf: buffer 0: URI \"/etc/passwd\" is an absolute path")
# A buffer of 1 GiB + 1 byte, sparse (no disk space), made for the test and
# removed after it.
find_program(VKT_TRUNCATE truncate)
if(VKT_TRUNCATE)
  add_test(NAME bad_input.10_gltf.huge_buffer.make
    COMMAND ${VKT_TRUNCATE} -s 1073741825 ${vkt_10_dir}/huge.bin)
  add_test(NAME bad_input.10_gltf.huge_buffer.remove
    COMMAND ${CMAKE_COMMAND} -E rm -f ${vkt_10_dir}/huge.bin)
  set_tests_properties(bad_input.10_gltf.huge_buffer.make PROPERTIES
    FIXTURES_SETUP vkt_10_huge LABELS chapter)
  set_tests_properties(bad_input.10_gltf.huge_buffer.remove PROPERTIES
    FIXTURES_CLEANUP vkt_10_huge LABELS chapter)
  vkt_chapter_test(bad_input.10_gltf.huge_buffer 10_gltf EXIT 1
    ARGS ${vkt_10_run} --model ${vkt_10_dir}/huge_buffer.gltf
    EXPECT "10_gltf: error: .*huge_buffer.gltf: .*huge.bin: is 1073741825 bytes, past the 1 GiB limit for one file")
  set_tests_properties(bad_input.10_gltf.huge_buffer PROPERTIES FIXTURES_REQUIRED vkt_10_huge)
endif()

# --- Issue 25: what tinygltf 2.7 itself trusts, checked before it sees the
# bytes (common/scene/src/gltf_guard.cpp). The files come from the fixture
# vkt_hostile_files (tests/make_hostile_files.cpp). Before the guard: exit 139
# (a stack overflow) and exit 0 (a file read past its end, and drawn).
vkt_chapter_test(bad_input.10_gltf.deep_extras 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/deep_extras.gltf
  EXPECT "10_gltf: error: .*deep_extras.gltf: JSON: arrays and objects nest more than 64 deep \\(at line 1, column [0-9]+\\); this loader's limit is 64 levels")
foreach(extra 4 8)
  vkt_chapter_test(bad_input.10_gltf.long_bin_chunk_${extra} 10_gltf EXIT 1
    ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/long_bin_chunk_${extra}.glb
    EXPECT "10_gltf: error: .*long_bin_chunk_${extra}.glb: .glb chunk 1 \\(BIN\\): its length, [0-9]+ bytes from byte [0-9]+, runs ${extra} bytes past the end of the file")
endforeach()
set_tests_properties(bad_input.10_gltf.deep_extras bad_input.10_gltf.long_bin_chunk_4
  bad_input.10_gltf.long_bin_chunk_8 PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# A PNG whose header claims 16384 x 16384 (3.7 GiB decoded, staged and
# mipmapped) in 69 bytes: refused from its header, before anything is
# allocated (unit.image budget* measure the peak memory).
vkt_chapter_test(bad_input.10_gltf.huge_image_claim 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/huge_claim.gltf
  EXPECT "10_gltf: error: .*huge_claim.gltf: image 0 \\(huge_claim.png\\): cannot decode image: it is 16384x16384: decoded, staged and mipmapped it would take 3755 MiB, past the 1 GiB limit \\(--max-memory\\)")
# The same for a JPEG: 8192 x 8192 fits the budget, but 156 bytes cannot hold
# its 1,048,576 blocks (a Huffman-coded JPEG spends a bit on each at least).
vkt_chapter_test(bad_input.10_gltf.jpeg_claim 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/jpeg_claim.gltf
  EXPECT "10_gltf: error: .*jpeg_claim.gltf: image 0 \\(huge_claim.jpg\\): cannot decode image: its header claims 8192x8192 pixels, which its 156 bytes cannot hold")
# The whole model's budget (--max-memory): a 50 MiB base64 data: URI (37.5
# MiB of buffer) is decoded by the loader, once, and the chapter draws its
# triangle (tinygltf alone peaked at 388 MB); with 64 MiB allowed, it is
# refused before it is decoded.
vkt_chapter_test(chapter.10_gltf.big_data_uri 10_gltf
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/big_data_uri.gltf
  EXPECT "big_data_uri.gltf: draws 1, primitives 1, materials 1, images 0, vertices 3")
vkt_chapter_test(bad_input.10_gltf.max_memory 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/big_data_uri.gltf --max-memory 64M
  EXPECT "10_gltf: error: .*big_data_uri.gltf: buffer 0: its data: URI, decoded: needs 38 MiB, which would bring what this file needs to 88 MiB, past the limit of 64 MiB \\(--max-memory\\)")
set_tests_properties(bad_input.10_gltf.huge_image_claim bad_input.10_gltf.jpeg_claim
  chapter.10_gltf.big_data_uri bad_input.10_gltf.max_memory PROPERTIES
  FIXTURES_REQUIRED vkt_hostile_files)
vkt_chapter_test(bad_input.10_gltf.max_memory_value 10_gltf EXIT 2 ARGS --max-memory lots
  EXPECT "10_gltf: --max-memory wants a size from 16 MiB to 1024 GiB \\(a number of bytes, or with K, M, G: 512M, 4G\\), not 'lots'")

# --- Issue 39: what got past the parser into our own loops. The files come
# from the fixture vkt_hostile_files (tests/make_hostile_files.cpp).
# A chain of 100,000 nodes, each the only child of the one before: walked on
# a stack of the loader's own. One call per level overflowed the thread's
# stack (exit 139 in the asan build; GCC's -O3 happens to turn it into a loop).
vkt_chapter_test(chapter.10_gltf.node_chain 10_gltf
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/node_chain.gltf
  EXPECT "node_chain.gltf: draws 1, primitives 1, materials 1, images 0, vertices 3, indices 3")
set_tests_properties(chapter.10_gltf.node_chain PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# 20,000 distinct extension names in extensionsUsed: each warning once (a
# hash set), the first 20 listed, then how many more. Before: all 20,000
# printed, each compared with every one before it (400,000 took 228 s), and
# no summary line.
vkt_chapter_test(chapter.10_gltf.warnings_20000 10_gltf
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/warnings_20000.gltf
  EXPECT "warnings_20000.gltf: warning: uses extension EXT_hostile_19, which this loader ignores"
         "warnings_20000.gltf: warning: and 19980 more warnings, not listed \\(this loader lists the first 20\\)"
         "warnings_20000.gltf: draws 1, primitives 1")
set_tests_properties(chapter.10_gltf.warnings_20000 PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# Counts a file sets that become Vulkan objects or per-draw work, each
# refused past a limit the message states (vkt/scene/gltf.hpp). 65,156 empty
# materials, a descriptor set each: before, 10 drew them (exit 0, 600 MB) and
# 23 aborted inside lavapipe ("LLVM ERROR: Unable to allocate section
# memory", signal 6). 2,000 nodes sharing one mesh of 300,000 vertices: 10
# transformed 600 million vertices for its bounds and drew them (10 s, exit 0).
vkt_chapter_test(bad_input.10_gltf.materials_65156 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/materials_65156.gltf
  EXPECT "10_gltf: error: .*materials_65156.gltf: materials: 65156 of them, past this loader's limit of 4096 \\(each becomes a descriptor set of its own\\)")
vkt_chapter_test(bad_input.10_gltf.instances_2000 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/instances_2000.gltf
  EXPECT "10_gltf: error: .*instances_2000.gltf: node 224: mesh 0: drawn here too, it brings the vertices drawn to 67200000, past this loader's limit of 67108864 \\(2\\^26: each node draws its mesh's vertices again\\)")
set_tests_properties(bad_input.10_gltf.materials_65156 bad_input.10_gltf.instances_2000
  PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# One NaN among finite numbers: a quad whose corner 2 has a NaN POSITION (y)
# or NORMAL (z). Before: exit 0, the quad missing (both triangles share the
# corner; glm::min and max skipped the NaN in the bounds) or lit from a NaN.
vkt_chapter_test(bad_input.10_gltf.nan_position 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/nan_position.gltf
  EXPECT "10_gltf: error: .*nan_position.gltf: mesh 0 primitive 0 POSITION: accessor 0: element 2, component 1, is NaN, not a finite number")
vkt_chapter_test(bad_input.10_gltf.nan_normal 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/nan_normal.gltf
  EXPECT "10_gltf: error: .*nan_normal.gltf: mesh 0 primitive 0 NORMAL: accessor 1: element 2, component 2, is NaN, not a finite number")
set_tests_properties(bad_input.10_gltf.nan_position bad_input.10_gltf.nan_normal
  PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# What tinygltf read wrong without a word, checked in the JSON it parsed
# (common/scene/src/gltf_values.cpp). Before: "mesh": 4294967296 was narrowed
# to 0 and mesh 0 drawn (exit 0); -2147483649 was reported as mesh
# 2147483647; a baseColorFactor of 2 numbers made tinygltf drop the whole
# pbrMetallicRoughness block and the triangle was drawn white (exit 0).
vkt_chapter_test(bad_input.10_gltf.mesh_2_32 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/mesh_2_32.gltf
  EXPECT "10_gltf: error: .*mesh_2_32.gltf: node 0: \"mesh\" is 4294967296, which is no index: glTF's are whole numbers from 0 to 2147483647")
vkt_chapter_test(bad_input.10_gltf.mesh_negative 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/mesh_negative.gltf
  EXPECT "10_gltf: error: .*mesh_negative.gltf: node 0: \"mesh\" is -2147483649, which is no index")
vkt_chapter_test(bad_input.10_gltf.base_color_2 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/base_color_2.gltf
  EXPECT "10_gltf: error: .*base_color_2.gltf: material 0 pbrMetallicRoughness: \"baseColorFactor\" has 2 numbers, not 4 \\(tinygltf would drop the whole pbrMetallicRoughness block, its textures too, without a word\\)")
set_tests_properties(bad_input.10_gltf.mesh_2_32 bad_input.10_gltf.mesh_negative
  bad_input.10_gltf.base_color_2 PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# The budget charges what is really allocated. POSITION of 2^24 zeros (no
# bufferView), not indexed, with --max-memory 200M: its floats (192 MiB) fit,
# the index list made for it (64 MiB) does not. Before, that list and the
# triangle list copied from it were not charged (with 2^27 and 1600M: a
# 2,716 MB peak), and the refusal came later, at "its vertices and indices".
vkt_chapter_test(bad_input.10_gltf.generated_indices 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/positions_2_24.gltf --max-memory 200M
  EXPECT "10_gltf: error: .*positions_2_24.gltf: mesh 0 primitive 0: its index list, generated: needs 64 MiB, which would bring what this file needs to [0-9]+ MiB, past the limit of 200 MiB \\(--max-memory\\)")
set_tests_properties(bad_input.10_gltf.generated_indices PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# 1 GiB of NULs as a model: refused from its first bytes, in a fraction of a
# second. Before: read whole (11 s, a 1.1 GB peak), then refused for what its
# JSON "values" would cost.
if(VKT_TRUNCATE)
  vkt_chapter_test(bad_input.10_gltf.nuls_1g 10_gltf EXIT 1
    ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/nuls_1g.gltf
    EXPECT "10_gltf: error: .*nuls_1g.gltf: not a glTF file: a .gltf is a JSON object, beginning with '\\{', and this begins with \"%00%00%00%00")
  set_tests_properties(bad_input.10_gltf.nuls_1g PROPERTIES FIXTURES_REQUIRED vkt_nuls)
endif()
# Messages in the FILE: ELEMENT: WHY form. An index accessor without a
# bufferView: tinygltf refuses it while reading the mesh, and the refusal
# was blamed on "node 0" ("node 0: tinygltf refuses it: accessor[1] invalid
# bufferView"); the mesh, the primitive and the accessor are named (by the
# loader itself under tinygltf 2.9, which lets it through, in the same words).
vkt_chapter_test(bad_input.10_gltf.indices_no_view 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/indices_no_view.gltf
  EXPECT "10_gltf: error: .*indices_no_view.gltf: mesh 0 primitive 0: index accessor 1 has no bufferView \\(or one that does not exist\\): glTF requires one for indices")
# A .glb whose BIN chunk is empty. Before: "buffer 0: tinygltf refuses it:
# Insufficient storage space for Chunk1(BIN data). At least Chunk1 Must have
# 4 bytes or more bytes, but got 4"; now the guard names the chunk.
vkt_chapter_test(bad_input.10_gltf.empty_bin_chunk 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/empty_bin_chunk.glb
  EXPECT "10_gltf: error: .*empty_bin_chunk.glb: .glb chunk 1 \\(BIN\\): it is empty, and a buffer is at least 1 byte long \\(a .glb with no binary data leaves its BIN chunk out\\)")
# An image's URI refused: tinygltf only warns about an image it cannot read,
# so no element was named ("FILE: URI ... leads out of ..."); now "image 0:".
vkt_chapter_test(bad_input.10_gltf.image_uri_outside 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/image_uri_outside.gltf
  EXPECT "10_gltf: error: .*image_uri_outside.gltf: image 0: URI \"\\.\\./outside\\.png\" leads out of the model's folder")
# A model's CMYK JPEG, in words (09's tests have the decoders' other refusals).
vkt_chapter_test(bad_input.10_gltf.cmyk_image 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model ${VKT_HOSTILE_DIR}/cmyk_image.gltf
  EXPECT "10_gltf: error: .*cmyk_image.gltf: image 0 \\(cmyk.jpg\\): cannot decode image: it is a CMYK JPEG \\(four inks, for print\\)")
# File names quoted and escaped where they are not plain: a trailing space
# shown inside the quotes, an escape sequence (ESC c, which resets a
# terminal and clears its screen) as \x1bc, not sent to the terminal.
# Before: printed raw.
string(ASCII 27 vkt_10_esc)
vkt_chapter_test(bad_input.10_gltf.name_trailing_space 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model "${VKT_HOSTILE_DIR}/trailing_space.gltf "
  EXPECT "10_gltf: error: \"[^\"]*/trailing_space.gltf \": not a glTF file")
vkt_chapter_test(bad_input.10_gltf.name_escape 10_gltf EXIT 1
  ARGS ${vkt_10_run} --model "${VKT_HOSTILE_DIR}/escape_${vkt_10_esc}c_reset.gltf"
  EXPECT "10_gltf: error: \"[^\"]*/escape_\\\\x1bc_reset.gltf\": not a glTF file")
set_tests_properties(bad_input.10_gltf.indices_no_view bad_input.10_gltf.empty_bin_chunk
  bad_input.10_gltf.image_uri_outside bad_input.10_gltf.cmyk_image
  bad_input.10_gltf.name_trailing_space bad_input.10_gltf.name_escape
  PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# A file of /proc, whose size reads as 0 bytes: it was called empty ("not a
# glTF file: it is empty"); its first bytes are read whatever its size says.
if(CMAKE_SYSTEM_NAME STREQUAL "Linux")
  vkt_chapter_test(bad_input.10_gltf.proc_file 10_gltf EXIT 1
    ARGS ${vkt_10_run} --model /proc/self/status
    EXPECT "10_gltf: error: /proc/self/status: not a glTF file: a .gltf is a JSON object, beginning with '\\{', and this begins with \"Name:")
endif()
# --model with an empty value: "needs a value", as every other flag says
# (it said "wants a value"), as --model= and as --model '' alike.
vkt_chapter_test(bad_input.10_gltf.model_empty 10_gltf EXIT 2 ARGS --model=
  EXPECT "10_gltf: --model needs a value")
add_test(NAME bad_input.10_gltf.model_empty_word
  COMMAND sh -c "\"$0\" --model '' 2>&1; echo \"exit $?\"" $<TARGET_FILE:10_gltf>)
set_tests_properties(bad_input.10_gltf.model_empty_word PROPERTIES LABELS chapter
  PASS_REGULAR_EXPRESSION "10_gltf: --model needs a value\n.*exit 2")
