# The house rules that the configure step checks (CONTRIBUTING.md explains
# them). Run at configure time, so a rule broken is a build that will not start.
#
# 1. Chapters stand alone: no file in chapters/ or shaders/NN_name/ includes
#    another chapter's file ("../NN_..."). What two chapters share belongs in
#    common/ (C++) or shaders/common/ (GLSL).
#    (also runnable on its own: cmake -DROOT=<tree> -P cmake/house_rules.cmake,
#    which the tests do on fixtures that break each rule)
# 2. common/ keeps its direction: a layer includes only itself and the layers
#    below it (domains and core at the bottom, then resources, frame, scene).
#    The include paths already enforce this for the compiler; this check says
#    which file broke it, and why, before the compiler does.
# 3. Every header of common/ begins (right after #pragma once) with a comment
#    that names the chapter that taught it ("chapter 03", "Chapter 16's",
#    "chapters 18-20"), so a reader can go from a helper to its lesson.

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_policy(VERSION 3.25)  # -P mode starts with old policies
endif()
if(NOT ROOT)
  set(ROOT ${PROJECT_SOURCE_DIR})
endif()
file(GLOB_RECURSE vkt_house_chapter_files
     ${ROOT}/chapters/*.cpp ${ROOT}/chapters/*.hpp
     ${ROOT}/shaders/[0-9][0-9]_*/*)
set(vkt_house_broken)
foreach(file IN LISTS vkt_house_chapter_files)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"\\.\\./")
  foreach(line IN LISTS lines)
    file(RELATIVE_PATH rel ${ROOT} ${file})
    string(STRIP "${line}" line)
    list(APPEND vkt_house_broken "  ${rel}: ${line}")
  endforeach()
endforeach()
if(vkt_house_broken)
  list(JOIN vkt_house_broken "\n" text)
  message(FATAL_ERROR "A chapter includes another chapter's file:\n${text}\n"
          "What two chapters share belongs in common/ (C++) or shaders/common/ (GLSL), "
          "naming the chapter that taught it (see CONTRIBUTING.md).")
endif()

# Each layer and the layers it may include (itself first).
set(vkt_layer_allows_domains   domains)
set(vkt_layer_allows_core      core)
set(vkt_layer_allows_resources resources core)
set(vkt_layer_allows_frame     frame resources core)
set(vkt_layer_allows_scene     scene frame resources core domains)
foreach(layer domains core resources frame scene)
  file(GLOB_RECURSE files ${ROOT}/common/${layer}/*.cpp
                          ${ROOT}/common/${layer}/*.hpp)
  foreach(file IN LISTS files)
    file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]*\"vkt/[a-z]+/")
    foreach(line IN LISTS lines)
      string(REGEX REPLACE ".*\"vkt/([a-z]+)/.*" "\\1" used "${line}")
      if(NOT used IN_LIST vkt_layer_allows_${layer})
        file(RELATIVE_PATH rel ${ROOT} ${file})
        list(APPEND vkt_house_broken "  ${rel} (layer ${layer}) includes layer ${used}")
      endif()
    endforeach()
  endforeach()
endforeach()
if(vkt_house_broken)
  list(JOIN vkt_house_broken "\n" text)
  message(FATAL_ERROR "An include runs against the layers of common/:\n${text}\n"
          "A layer may include only the layers below it (see common/CMakeLists.txt).")
endif()

# A header's first comment: the // lines right after #pragma once, joined into
# one line so that "chapter" and its number may stand on two lines.
file(GLOB_RECURSE vkt_house_headers ${ROOT}/common/*/include/*.hpp)
foreach(file IN LISTS vkt_house_headers)
  file(READ ${file} text LIMIT 4096)
  set(comment "")
  if(text MATCHES "^#pragma once\n((//[^\n]*\n)+)")
    string(REGEX REPLACE "\n//" " " comment "${CMAKE_MATCH_1}")
  endif()
  if(NOT comment MATCHES "[Cc]hapters? +[0-9][0-9]")
    file(RELATIVE_PATH rel ${ROOT} ${file})
    list(APPEND vkt_house_broken "  ${rel}")
  endif()
endforeach()
if(vkt_house_broken)
  list(JOIN vkt_house_broken "\n" text)
  message(FATAL_ERROR "A header of common/ does not name the chapter that taught it:\n${text}\n"
          "Begin it, right after #pragma once, with a comment such as "
          "\"// ..., taught in chapter 07.\" (see CONTRIBUTING.md).")
endif()
