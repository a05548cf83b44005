# VKT_BLESS=1 rewrites a golden image only from the test that owns it (the
# checker's --blesses): run as chapter_check.bless_only_owner with
#   cmake -DCHECKER=... -DCHAPTER=<17_tiled_deferred> -DGOLDEN=<a golden image>
#         -DWORK=<scratch folder> -DARGS=<the chapter's arguments> -P bless_only_owner.cmake
# A copy of GOLDEN (another picture than the chapter draws) stands in for the
# golden image. Without --blesses, a run under VKT_BLESS=1 must compare, fail,
# and leave the copy as it was; with --blesses, the same run must replace it.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
configure_file(${GOLDEN} ${WORK}/golden.png COPYONLY)
file(SHA256 ${WORK}/golden.png before)
set(ENV{VKT_BLESS} 1)
separate_arguments(chapter_args UNIX_COMMAND "${ARGS}")
execute_process(COMMAND ${CHECKER} --exe ${CHAPTER} --out ${WORK} --name not_owner
                        --golden ${WORK}/golden.png -- ${chapter_args}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(SHA256 ${WORK}/golden.png after)
if(NOT after STREQUAL before)
  message(FATAL_ERROR "a test without --blesses rewrote the golden image under VKT_BLESS=1")
endif()
if(status EQUAL 0 OR NOT err MATCHES "FAIL: picture differs from")
  message(FATAL_ERROR "a test without --blesses did not compare (exit ${status}):\n${out}\n${err}")
endif()
message(STATUS "without --blesses: compared, failed, golden image untouched")
execute_process(COMMAND ${CHECKER} --exe ${CHAPTER} --out ${WORK} --name owner
                        --golden ${WORK}/golden.png --blesses -- ${chapter_args}
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(SHA256 ${WORK}/golden.png blessed)
file(SHA256 ${WORK}/owner.png drawn)
if(NOT status EQUAL 0 OR NOT blessed STREQUAL drawn)
  message(FATAL_ERROR "the owner did not bless (exit ${status}):\n${out}\n${err}")
endif()
message(STATUS "with --blesses: the golden image is the new picture")
