# Lists every file past its page and fails if there is one (CTest: house.file_limits).
#   cmake -DROOT=<repository> -P cmake/check_file_limits.cmake
# A chapter's main.cpp reads beside its book page: under 450 lines. A
# chapter's local header holds one pass or one part: under 250. A source of
# common/ is one helper, small enough to read in one sitting: under 450.
# A file at its limit is over it (house.file_limits_can_fail writes files of
# 449, 450 and 461 lines, and 249 and 250, to show where the line falls).
if(CMAKE_SCRIPT_MODE_FILE)
  cmake_policy(VERSION 3.25)  # -P mode starts with old policies
endif()
if(NOT ROOT)
  get_filename_component(ROOT ${CMAKE_CURRENT_LIST_DIR}/.. ABSOLUTE)
endif()
set(over "")
# A macro, not a function: it adds to `over` in the caller's scope.
macro(vkt_limit limit)
  foreach(file IN ITEMS ${ARGN})
    file(READ ${file} text)
    string(REGEX MATCHALL "\n" newlines "${text}")
    list(LENGTH newlines n)
    # A last line without its newline is a line too.
    if(NOT text STREQUAL "" AND NOT text MATCHES "\n$")
      math(EXPR n "${n} + 1")
    endif()
    if(NOT n LESS ${limit})
      file(RELATIVE_PATH rel ${ROOT} ${file})
      string(APPEND over "  ${rel}: ${n} lines (must be under ${limit})\n")
    endif()
  endforeach()
endmacro()
file(GLOB mains ${ROOT}/chapters/*/main.cpp)
file(GLOB chapter_headers ${ROOT}/chapters/*/*.hpp ${ROOT}/chapters/*/*.h)
file(GLOB_RECURSE common_sources ${ROOT}/common/*.cpp ${ROOT}/common/*.hpp)
vkt_limit(450 ${mains})
vkt_limit(250 ${chapter_headers})
vkt_limit(450 ${common_sources})
if(over)
  message(FATAL_ERROR "Files past their page:\n${over}"
          "Split along the concepts (CONTRIBUTING.md, 'No file past its page').")
endif()
message(STATUS "every chapter main.cpp and common/ source under 450 lines, every chapter header under 250")
