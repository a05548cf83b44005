# What to do when a dependency is missing, said in each system's own words.
#
# vkt_missing_dependency(<what> APT <debian 12 and ubuntu 24.04 names>
#                        [DEBIAN <Debian 12 only>] [UBUNTU <Ubuntu 24.04 only>]
#                        FEDORA <names> ARCH <names> ELSEWHERE <how>
#                        [OTHERWISE <a way round it, e.g. an option to turn off>])
# stops the configure step with the package to install on every system that
# scripts/install-deps.sh knows (Fedora and Arch names as we believe them).
function(vkt_missing_dependency what)
  cmake_parse_arguments(ARG "" "APT;DEBIAN;UBUNTU;FEDORA;ARCH;ELSEWHERE;OTHERWISE" "" ${ARGN})
  set(otherwise "")
  if(ARG_OTHERWISE)
    set(otherwise "Or ${ARG_OTHERWISE}.\n")
  endif()
  if(NOT ARG_DEBIAN)
    set(ARG_DEBIAN "${ARG_APT}")
  endif()
  if(NOT ARG_UBUNTU)
    set(ARG_UBUNTU "${ARG_APT}")
  endif()
  message(FATAL_ERROR
    "Missing: ${what}. Install it:\n"
    "  Debian 12:      apt install ${ARG_DEBIAN}   (scripts/install-deps.sh installs everything)\n"
    "  Ubuntu 24.04:   apt install ${ARG_UBUNTU}   (likewise)\n"
    "  Fedora:         dnf install ${ARG_FEDORA}\n"
    "  Arch:           pacman -S ${ARG_ARCH}\n"
    "  Windows, macOS: ${ARG_ELSEWHERE}\n"
    "${otherwise}"
    "Installed somewhere CMake does not look? Add its prefix to CMAKE_PREFIX_PATH.")
endfunction()

# vkt_find_package(<package> [VERSION <v>] WHAT <text> APT <names> [DEBIAN ...]
#                  [UBUNTU ...] FEDORA <names> ARCH <names> ELSEWHERE <how>)
# find_package, and where it finds nothing, vkt_missing_dependency. A macro, so
# that what find_package sets (<package>_FOUND, its targets) stays visible.
macro(vkt_find_package vkt_package)
  cmake_parse_arguments(_vkt_find "" "VERSION;WHAT;APT;DEBIAN;UBUNTU;FEDORA;ARCH;ELSEWHERE" ""
                        ${ARGN})
  # A package the build provides itself (VKT_PROVIDED_PACKAGES: the Windows
  # build's, cmake/windows.cmake) is not looked for.
  if(NOT "${vkt_package}" IN_LIST VKT_PROVIDED_PACKAGES)
    find_package(${vkt_package} ${_vkt_find_VERSION} QUIET)
  endif()
  if(NOT ${vkt_package}_FOUND)
    string(STRIP "${vkt_package} ${_vkt_find_VERSION}" _vkt_find_call)
    vkt_missing_dependency("${_vkt_find_WHAT} (find_package(${_vkt_find_call}))"
      APT "${_vkt_find_APT}" DEBIAN "${_vkt_find_DEBIAN}" UBUNTU "${_vkt_find_UBUNTU}"
      FEDORA "${_vkt_find_FEDORA}" ARCH "${_vkt_find_ARCH}" ELSEWHERE "${_vkt_find_ELSEWHERE}")
  endif()
endmacro()
