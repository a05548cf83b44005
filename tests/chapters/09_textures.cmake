# Chapter 09: a textured floor receding to the horizon, with mip maps.
#
# Hand-worked pixels: the top corners are sky, the clear colour linear
# (0.25, 0.45, 0.80), which the _SRGB target stores sRGB-encoded as
# (137, 179, 231): 1.055 * c^(1/2.4) - 0.055, times 255, rounded
# (136.96, 178.86, 231.11). A raw UNORM store would give (64, 115, 204).
set(VKT_09_PIXEL PIXEL 0,0,137,179,231 319,0,137,179,231)
vkt_chapter_test(chapter.09_textures 09_textures GOLDEN BLESS ${VKT_09_PIXEL} ARGS ${headless}
  EXPECT "09_textures: checker.png, 256x256, 9 mip levels \\(blit\\)")
vkt_chapter_test(chapter.09_textures.offscreen 09_textures SAME_AS chapter.09_textures ${VKT_09_PIXEL} ARGS ${offscreen})
vkt_chapter_window_test(09_textures PIXEL 0,0,137,179,231)

# The CPU fallback (a box filter averaging in linear light) makes nearly the
# same mips as lavapipe's linear blits: against the same golden image, 12% of
# the pixels a level or two apart, a bias of 0.09 (the two filters round the
# far floor's texels differently), so the golden tolerance with a bias of
# up to 0.2 (a picture 2% brighter moves it by 1.7).
vkt_chapter_test(chapter.09_textures.cpu_mips 09_textures GOLDEN ${VKT_09_PIXEL}
  TOLERANCE 2,24,0.002,0.2,1 ARGS ${headless} --mips cpu EXPECT "9 mip levels \\(cpu\\)")
# Without mips the far floor aliases (the book shows it): no golden image,
# but it must run cleanly and say what it does.
vkt_chapter_test(chapter.09_textures.no_mips 09_textures ${VKT_09_PIXEL}
  ARGS ${headless} --mips none --anisotropy 1
  EXPECT "1 mip level \\(none\\), anisotropic filtering off")
vkt_chapter_test(chapter.09_textures.help 09_textures EXIT 0 ARGS --help
  EXPECT "usage: 09_textures" "--texture FILE" "--mips blit\\|cpu\\|none")

# Bad input: a missing texture, a file that is no PNG or JPEG, a --mips it
# does not know.
vkt_chapter_test(bad_input.09_textures.missing_texture 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${CMAKE_CURRENT_BINARY_DIR}/no-such-texture.png
  EXPECT "cannot open .*no-such-texture.png")
set(VKT_09_GARBAGE ${CMAKE_CURRENT_BINARY_DIR}/09_textures_garbage.png)
file(WRITE ${VKT_09_GARBAGE} "this is not a PNG file")
vkt_chapter_test(bad_input.09_textures.corrupt_texture 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_09_GARBAGE}
  EXPECT "09_textures_garbage.png: cannot decode image")
# The texture is read by vkt::read_file: a directory, or a file past 1 GiB
# (sparse, made for the test and removed after it), is one line naming it.
vkt_chapter_test(bad_input.09_textures.directory_texture 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${CMAKE_CURRENT_BINARY_DIR}
  EXPECT "09_textures: error: .*: is a directory, not a file")
find_program(VKT_TRUNCATE truncate)
if(VKT_TRUNCATE)
  set(VKT_09_HUGE ${CMAKE_CURRENT_BINARY_DIR}/09_textures_huge.png)
  add_test(NAME bad_input.09_textures.huge_texture.make
    COMMAND ${VKT_TRUNCATE} -s 1073741825 ${VKT_09_HUGE})
  add_test(NAME bad_input.09_textures.huge_texture.remove
    COMMAND ${CMAKE_COMMAND} -E rm -f ${VKT_09_HUGE})
  set_tests_properties(bad_input.09_textures.huge_texture.make PROPERTIES
    FIXTURES_SETUP vkt_09_huge LABELS chapter)
  set_tests_properties(bad_input.09_textures.huge_texture.remove PROPERTIES
    FIXTURES_CLEANUP vkt_09_huge LABELS chapter)
  vkt_chapter_test(bad_input.09_textures.huge_texture 09_textures EXIT 1
    ARGS --headless --frames 1 --texture ${VKT_09_HUGE}
    EXPECT "09_textures: error: .*09_textures_huge.png: is 1073741825 bytes, past the 1 GiB limit for one file")
  set_tests_properties(bad_input.09_textures.huge_texture PROPERTIES FIXTURES_REQUIRED vkt_09_huge)
endif()
# --max-memory: a true 4096 x 4096 JPEG (64 KiB of flat grey, from the
# fixture vkt_hostile_files) costs 235 MiB decoded, staged and mipmapped,
# judged from its header before a pixel is decoded; one that claims 8192 x
# 8192 in 156 bytes is refused for the bytes it lacks.
vkt_chapter_test(bad_input.09_textures.max_memory 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/flat_4096.jpg --max-memory 128M
  EXPECT "09_textures: error: .*flat_4096.jpg: cannot decode image: it is 4096x4096: decoded, staged and mipmapped it would take 235 MiB, past the 128 MiB limit \\(--max-memory\\) with the 64 KiB the file needs besides")
vkt_chapter_test(bad_input.09_textures.jpeg_claim 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/huge_claim.jpg
  EXPECT "09_textures: error: .*huge_claim.jpg: cannot decode image: its header claims 8192x8192 pixels, which its 156 bytes cannot hold")
# With --mips cpu the chain is made in memory of its own first: 85 MiB more.
vkt_chapter_test(bad_input.09_textures.max_memory_cpu_mips 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/flat_4096.jpg --mips cpu --max-memory 240M
  EXPECT "09_textures: error: .*flat_4096.jpg: its mip chain, made on the CPU: needs 85 MiB, which would bring what this file needs to 320 MiB, past the limit of 240 MiB \\(--max-memory\\)")
set_tests_properties(bad_input.09_textures.max_memory bad_input.09_textures.jpeg_claim
  bad_input.09_textures.max_memory_cpu_mips PROPERTIES
  FIXTURES_REQUIRED vkt_hostile_files)
vkt_chapter_test(bad_input.09_textures.bad_mips 09_textures EXIT 2 ARGS --mips trilinear
  EXPECT "--mips wants one of blit, cpu, none, not 'trilinear'")

# Anisotropic filtering is left to the implementation in its details, so the
# default picture differs from GPU to GPU (book/09_textures.md). The same view
# without it is the picture every device must reproduce: scripts/gpu-check.sh
# compares a GPU's run with this reference.
set(test chapter.09_textures.anisotropy_off)
add_test(NAME ${test} COMMAND vkt_chapter_check --exe $<TARGET_FILE:09_textures>
  --out ${VKT_TEST_OUTPUT} --name ${test}
  --golden ${VKT_GOLDEN_DIR}/09_textures_anisotropy_off.png --blesses
  --pixel 0,0,137,179,231 --pixel 319,0,137,179,231
  --expect "anisotropic filtering off" -- ${headless} --anisotropy 1)
set_tests_properties(${test} PROPERTIES ENVIRONMENT "VK_DRIVER_FILES=${VKT_LAVAPIPE_ICD}"
  LABELS "chapter;bless")

# Issue 39: a palette PNG whose pixels use index 5 of a palette of 1 colour
# (tests/make_hostile_files.cpp). Before: exit 0, drawn black (libpng's
# expansion looks nothing up and says nothing); the indices are now looked
# up by the decoder, each checked.
vkt_chapter_test(bad_input.09_textures.palette_index 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/palette_index.png
  EXPECT "09_textures: error: .*palette_index.png: cannot decode image: pixel \\(1, 0\\) is palette index 5, past the end of its palette of 1 colours")
set_tests_properties(bad_input.09_textures.palette_index PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
# 1 GiB of NULs as a texture, with --max-memory 512M: refused from its first
# bytes as not a PNG or JPEG. Before: its size was charged first (the budget's
# refusal); with the default budget it was read whole (8 s, a 1.1 GB peak).
if(VKT_TRUNCATE)
  vkt_chapter_test(bad_input.09_textures.nuls_1g 09_textures EXIT 1
    ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/nuls_1g.png --max-memory 512M
    EXPECT "09_textures: error: .*nuls_1g.png: cannot decode image: not a PNG or JPEG file")
  set_tests_properties(bad_input.09_textures.nuls_1g PROPERTIES FIXTURES_REQUIRED vkt_nuls)
endif()
# Decoders' jargon said in words (common/resources/src/image_messages.cpp),
# on pictures written by tests/make_hostile_files.cpp. Before, in libjpeg's
# and libpng's own words: "Unsupported color conversion request", "Empty
# JPEG image (DNL not supported)", "IEND: out of place", "Invalid IHDR data".
vkt_chapter_test(bad_input.09_textures.cmyk_jpeg 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/cmyk.jpg
  EXPECT "09_textures: error: .*cmyk.jpg: cannot decode image: it is a CMYK JPEG \\(four inks, for print\\), which this loader does not convert to RGB: save it as an RGB JPEG or a PNG")
vkt_chapter_test(bad_input.09_textures.dnl_jpeg 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/dnl.jpg
  EXPECT "09_textures: error: .*dnl.jpg: cannot decode image: its header gives a height of 0: the height would come after the first scan, in a DNL marker, which libjpeg-turbo does not read")
vkt_chapter_test(bad_input.09_textures.png_chunk_out_of_place 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/iend_out_of_place.png
  EXPECT "09_textures: error: .*iend_out_of_place.png: cannot decode image: its end chunk \\(IEND\\) is out of place: a PNG is its header \\(IHDR\\) first, .* and its end \\(IEND\\) last")
vkt_chapter_test(bad_input.09_textures.png_invalid_header 09_textures EXIT 1
  ARGS --headless --frames 1 --texture ${VKT_HOSTILE_DIR}/ihdr_zero_width.png
  EXPECT "09_textures: error: .*ihdr_zero_width.png: cannot decode image: its header chunk \\(IHDR\\) is invalid: image width is zero")
set_tests_properties(bad_input.09_textures.cmyk_jpeg bad_input.09_textures.dnl_jpeg
  bad_input.09_textures.png_chunk_out_of_place bad_input.09_textures.png_invalid_header
  PROPERTIES FIXTURES_REQUIRED vkt_hostile_files)
