# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (the posix thread
# model: std::thread and std::mutex need it). scripts/windows-build.sh uses
# this file; by hand:
#
#   cmake -S . -B build/windows -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64-x86_64.cmake \
#         -DVKT_MINGW_DEPS=$PWD/build/mingw-deps
#
# VKT_MINGW_DEPS is the prefix holding the libraries built for the target
# (GLFW, zlib, libpng, libjpeg-turbo, Catch2); the header-only ones come from
# the host (cmake/windows.cmake says which and how they are used).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)

set(VKT_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${VKT_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${VKT_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${VKT_MINGW_TRIPLE}-windres)

# The deps prefix travels to try_compile projects too.
set(CMAKE_TRY_COMPILE_PLATFORM_VARIABLES VKT_MINGW_DEPS)
if(NOT VKT_MINGW_DEPS AND DEFINED ENV{VKT_MINGW_DEPS})
  set(VKT_MINGW_DEPS $ENV{VKT_MINGW_DEPS})
endif()

# Libraries and headers only from the MinGW sysroot and the deps prefix,
# never the host's /usr; programs (glslangValidator, python3) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${VKT_MINGW_TRIPLE} ${VKT_MINGW_DEPS})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# The C and C++ runtimes linked in, so an .exe needs no MinGW DLL beside it.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static-libgcc -static-libstdc++ -static")

# Programs built for the target run under Wine (try_run, and CTest where used).
find_program(VKT_WINE NAMES wine wine64)
if(VKT_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${VKT_WINE})
endif()
