# Chapter 27: threads (4,097 objects recorded into secondary command buffers
# by N threads, one command pool per thread per frame slot) and a pipeline
# cache on disk.
#
# The sky is the clear colour, linear (0.30, 0.45, 0.65), stored sRGB-encoded
# as (149, 179, 211) in the top corners. Two floor pixels, worked out by hand
# from threads.frag: the floor is linear grey 0.5, its normal +y, so
# lambert = dot(+y, normalize(0.4, 1, 0.3)) = 1 / sqrt(1.25) = 0.8944 and the
# light 0.25 + 0.75 * 0.8944 = 0.9208: 0.5 * 0.9208 = 0.4604, sRGB 180.7,
# stored 181 (within 1: it lies 0.2 from the rounding boundary). Unlit it
# would be 188, lambert alone 178, the linear value stored raw 117. Each lies
# in a 9 x 9 patch of bare floor between the objects near the bottom.
set(VKT_27_PIXEL PIXEL 0,0,149,179,211 319,0,149,179,211 164,230,181,181,181,1 213,199,181,181,181,1)
set(VKT_27_START
  "27_threads: 4097 objects \\(64 x 64 and the floor\\), one draw each, recorded by [0-9]+ threads? into secondary command buffers \\([0-9]+ command pools: [0-9]+ per frame slot\\)")
vkt_chapter_test(chapter.27_threads 27_threads GOLDEN BLESS ${VKT_27_PIXEL} ARGS ${headless}
  EXPECT ${VKT_27_START} "the pipeline took [0-9.]+ ms to create \\(no pipeline cache\\)")
vkt_chapter_test(chapter.27_threads.offscreen 27_threads SAME_AS chapter.27_threads ${VKT_27_PIXEL}
  ARGS ${offscreen} EXPECT ${VKT_27_START})
vkt_chapter_window_test(27_threads PIXEL 0,0,149,179,211)

# The same picture, to the bit, whatever the number of threads: the shares
# are consecutive runs of the objects, executed in thread order, so the GPU
# gets the same draws in the same order. 7 splits 4,097 unevenly (585 or 586
# each); the default is the machine's processor count.
foreach(threads 1 2 4 7)
  vkt_chapter_test(chapter.27_threads.threads_${threads} 27_threads SAME_AS chapter.27_threads
    ${VKT_27_PIXEL} ARGS ${headless} --threads ${threads}
    EXPECT "recorded by ${threads} threads? into secondary command buffers \\([0-9]+ command pools: ${threads} per frame slot\\)")
endforeach()
# More threads than objects (2 objects, 64 threads): 62 secondaries that draw
# nothing are still begun, ended and executed, and validation stays quiet.
vkt_chapter_test(chapter.27_threads.more_threads_than_objects 27_threads
  PIXEL 319,0,149,179,211 5,235,181,181,181,1 ARGS ${headless} --grid 1 --threads 64
  EXPECT "2 objects \\(1 x 1 and the floor\\), one draw each, recorded by 64 threads")

# --benchmark: the GPU's "draw" scope, and the CPU's time from fork to join.
vkt_chapter_test(chapter.27_threads.benchmark 27_threads
  ARGS --headless --no-validation --frames 5 --size ${VKT_TEST_SIZE} --benchmark --threads 2
  EXPECT "\"gpu_scopes_ms\": \\{\"draw\": \\{\"min\": [0-9.]+, \"median\": [0-9.]+, \"p95\": [0-9.]+"
         "recording the draws on 2 threads took [0-9.]+ ms median, [0-9.]+ ms p95 on the CPU \\(5 frames\\)")
vkt_chapter_test(chapter.27_threads.help 27_threads EXIT 0 ARGS --help
  EXPECT "usage: 27_threads" "--threads N" "--grid N" "--pipeline-cache FILE")

# The pipeline cache. Each test has a file of its own (tests run in
# parallel); the cold and the warm run share one, in that order (fixtures),
# and a setup test first removes what an earlier run left there.
set(VKT_27_CACHE ${CMAKE_CURRENT_BINARY_DIR}/27_threads_cache)
file(MAKE_DIRECTORY ${VKT_27_CACHE})
# vkt_27_add_fixture(<test> REQUIRED|SETUP <fixture>): adds to the test's
# fixtures (vkt_same_picture has set some already).
function(vkt_27_add_fixture test kind fixture)
  get_test_property(${test} FIXTURES_${kind} fixtures)
  if(NOT fixtures)
    set(fixtures)
  endif()
  list(APPEND fixtures ${fixture})
  set_tests_properties(${test} PROPERTIES FIXTURES_${kind} "${fixtures}")
endfunction()
add_test(NAME chapter.27_threads.cache_cold_setup
  COMMAND ${CMAKE_COMMAND} -E rm -f ${VKT_27_CACHE}/cold_then_warm.cache)
set_tests_properties(chapter.27_threads.cache_cold_setup PROPERTIES
  FIXTURES_SETUP chapter27_no_cache LABELS chapter)
# Cold: no file, so an empty cache; the pipeline is compiled and saved.
vkt_chapter_test(chapter.27_threads.cache_cold 27_threads SAME_AS chapter.27_threads
  ARGS ${headless} --pipeline-cache ${VKT_27_CACHE}/cold_then_warm.cache
  EXPECT "pipeline cache .*cold_then_warm.cache: no file yet, starting cold"
         "the pipeline took [0-9.]+ ms to create \\(an empty pipeline cache\\)"
         "pipeline cache .*cold_then_warm.cache: saved [1-9][0-9]* bytes")
vkt_27_add_fixture(chapter.27_threads.cache_cold REQUIRED chapter27_no_cache)
vkt_27_add_fixture(chapter.27_threads.cache_cold SETUP chapter27_cache_saved)
# Warm: the file the cold run saved is this device's, and is loaded.
vkt_chapter_test(chapter.27_threads.cache_warm 27_threads SAME_AS chapter.27_threads
  ARGS ${headless} --pipeline-cache ${VKT_27_CACHE}/cold_then_warm.cache
  EXPECT "pipeline cache .*cold_then_warm.cache: loaded [1-9][0-9]* bytes made by this device"
         "the pipeline took [0-9.]+ ms to create \\(a pipeline cache loaded from the file\\)")
vkt_27_add_fixture(chapter.27_threads.cache_warm REQUIRED chapter27_cache_saved)
# A corrupt file and another device's: ignored in one line, a cold start,
# exit 0 and the same picture (and each is then overwritten with a good
# cache, so a setup test writes it again before every run).
find_package(Python3 COMPONENTS Interpreter QUIET)  # required (tests/CMakeLists.txt says so)
foreach(kind corrupt foreign)
  add_test(NAME chapter.27_threads.cache_${kind}_setup
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_SOURCE_DIR}/chapters/27_cache_file.py ${kind}
            ${VKT_27_CACHE}/${kind}.cache)
  set_tests_properties(chapter.27_threads.cache_${kind}_setup PROPERTIES
    FIXTURES_SETUP chapter27_${kind}_cache LABELS chapter)
endforeach()
vkt_chapter_test(chapter.27_threads.cache_corrupt 27_threads SAME_AS chapter.27_threads
  ARGS ${headless} --pipeline-cache ${VKT_27_CACHE}/corrupt.cache
  EXPECT "pipeline cache .*corrupt.cache ignored, starting cold: not a pipeline cache \\(header size [0-9]+, version [0-9]+; expected 32, 1\\)"
         "\\(an empty pipeline cache\\)")
vkt_27_add_fixture(chapter.27_threads.cache_corrupt REQUIRED chapter27_corrupt_cache)
vkt_chapter_test(chapter.27_threads.cache_foreign 27_threads SAME_AS chapter.27_threads
  ARGS ${headless} --pipeline-cache ${VKT_27_CACHE}/foreign.cache
  EXPECT "pipeline cache .*foreign.cache ignored, starting cold: made by another device or driver \\(vendor 0x10de, device 0x2330, cache UUID abababababababababababababababab; this one is .*\\)"
         "\\(an empty pipeline cache\\)")
vkt_27_add_fixture(chapter.27_threads.cache_foreign REQUIRED chapter27_foreign_cache)
# Where the cache cannot be saved (no such folder): one line, and the run
# goes on (exit 0): a cache only saves time.
vkt_chapter_test(chapter.27_threads.cache_unwritable 27_threads PIXEL 0,0,149,179,211
  ARGS --headless --validation --frames 1 --size ${VKT_TEST_SIZE}
       --pipeline-cache ${VKT_27_CACHE}/no-such-folder/x.cache
  EXPECT "pipeline cache .*no-such-folder/x.cache: could not save it")

# Bad input: the command line (exit 2).
vkt_chapter_test(bad_input.27_threads.threads_zero 27_threads EXIT 2 ARGS --threads 0
  EXPECT "--threads wants a whole number from 1 to 64, not '0'")
vkt_chapter_test(bad_input.27_threads.threads_too_many 27_threads EXIT 2 ARGS --threads 65
  EXPECT "--threads wants a whole number from 1 to 64, not '65'")
vkt_chapter_test(bad_input.27_threads.threads_word 27_threads EXIT 2 ARGS --threads many
  EXPECT "--threads wants a whole number from 1 to 64, not 'many'")
vkt_chapter_test(bad_input.27_threads.grid 27_threads EXIT 2 ARGS --grid 257
  EXPECT "--grid wants a whole number from 1 to 256, not '257'")
vkt_chapter_test(bad_input.27_threads.pipeline_cache_missing 27_threads EXIT 2
  ARGS --pipeline-cache EXPECT "--pipeline-cache needs a value")
