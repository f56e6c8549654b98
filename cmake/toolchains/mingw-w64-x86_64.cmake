# Cross build for 64-bit Windows with Debian's MinGW-w64 (package g++-mingw-w64-x86-64, the win32
# thread model: no libwinpthread to carry). Used by scripts/build --platforms ...,win64 and by
# scripts/setup for the target's SUNDIALS. Programs built for the target run under wine64.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(UC_MINGW_PREFIX x86_64-w64-mingw32)

set(CMAKE_C_COMPILER ${UC_MINGW_PREFIX}-gcc)
set(CMAKE_CXX_COMPILER ${UC_MINGW_PREFIX}-g++)
set(CMAKE_RC_COMPILER ${UC_MINGW_PREFIX}-windres)

# Libraries and headers of the target only from the target's root and the prefixes given with
# CMAKE_PREFIX_PATH (the cross-built SUNDIALS); programs (python, the compiler) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${UC_MINGW_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Test programs of the target run through wine64 (ctest, try_run).
find_program(UC_WINE64 NAMES wine64 PATHS /usr/lib/wine NO_DEFAULT_PATH)
if(NOT UC_WINE64)
  find_program(UC_WINE64 NAMES wine64 wine)
endif()
if(UC_WINE64)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${UC_WINE64})
endif()
