# Cross-compiling Stepwise for Windows with Debian's mingw-w64 (POSIX threads flavour), so the
# DirectX 12 demo shell can be built and tested on Linux under wine (docs/renderer.md).
#   cmake --preset mingw      (or: cmake -B build/mingw -DCMAKE_TOOLCHAIN_FILE=cmake/toolchain-mingw.cmake)
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(mingw_triple x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${mingw_triple}-gcc-posix)
set(CMAKE_CXX_COMPILER ${mingw_triple}-g++-posix)
set(CMAKE_RC_COMPILER ${mingw_triple}-windres)

# Libraries and headers from mingw only; programs from the host. Packages (CMake config files)
# from both: Eigen, nlohmann-json and CLI11 are header-only Debian packages whose config files
# live in /usr/share, outside the mingw root.
set(CMAKE_FIND_ROOT_PATH /usr/${mingw_triple})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
list(APPEND CMAKE_PREFIX_PATH /usr/share/eigen3/cmake /usr/share/cmake/CLI11 /usr/share/cmake/nlohmann_json)

# One self-contained .exe per demo: no libstdc++/libgcc/winpthread DLLs to ship next to it.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -static-libgcc -static-libstdc++")
# Big Eigen-heavy objects exceed the PE/COFF section limit without this.
set(CMAKE_CXX_FLAGS_INIT "-Wa,-mbig-obj")

find_program(STEPWISE_WINE64 NAMES wine64 PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(STEPWISE_WINE64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${STEPWISE_WINE64})
endif()

# nlohmann-json and CLI11 export /usr/include as their include directory, and putting the
# host's /usr/include on a mingw compile line would shadow mingw's own C headers with glibc's.
# After project() (CMAKE_PROJECT_INCLUDE runs this file again), load those packages first and
# point them at a folder that holds only their own header trees.
if(STEPWISE_MINGW_PROJECT_HOOK)
  if(CMAKE_PROJECT_NAME STREQUAL "Stepwise" AND NOT TARGET nlohmann_json::nlohmann_json)
    set(shadow ${CMAKE_BINARY_DIR}/host-headers)
    file(MAKE_DIRECTORY ${shadow})
    foreach(tree nlohmann CLI)
      if(NOT EXISTS ${shadow}/${tree} AND EXISTS /usr/include/${tree})
        file(CREATE_LINK /usr/include/${tree} ${shadow}/${tree} SYMBOLIC)
      endif()
    endforeach()
    find_package(nlohmann_json 3 QUIET)
    find_package(CLI11 QUIET)
    # Header-only, so every target may see them, as natively through /usr/include (a chapter
    # that includes <CLI/CLI.hpp> without linking CLI11 still builds the same on both).
    include_directories(SYSTEM ${shadow})
    foreach(target nlohmann_json::nlohmann_json CLI11::CLI11)
      if(TARGET ${target})
        set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${shadow})
      endif()
    endforeach()
  endif()
else()
  set(STEPWISE_MINGW_PROJECT_HOOK ON)
  set(CMAKE_PROJECT_INCLUDE ${CMAKE_CURRENT_LIST_FILE})
endif()
