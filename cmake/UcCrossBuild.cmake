# The binaries of the platforms in UC_PLATFORMS other than this tree's own: win64 from linux64, a cross
# build of this same source tree with MinGW-w64 (cmake/toolchains/mingw-w64-x86_64.cmake) in
# <build>/win64, against a SUNDIALS built for Windows by scripts/setup (docs/platforms.md). It runs as part
# of every build of this tree, incrementally, so the FMUs never pack a stale foreign binary.
#   UC_FOREIGN_PLATFORMS             the platforms cross-built here
#   UC_FOREIGN_BINARY_DIR_<platform> the cross tree: <dir>/fmu/<Name>.dll, <dir>/fmu/partners/<Name>.dll
#   UC_FOREIGN_DEPENDS               the targets that build them
set(UC_FOREIGN_PLATFORMS "")
set(UC_FOREIGN_DEPENDS "")
foreach(platform IN LISTS UC_PLATFORMS)
  if(platform STREQUAL UC_FMI_PLATFORM)
    continue()
  endif()
  if(NOT (platform STREQUAL "win64" AND UC_FMI_PLATFORM STREQUAL "linux64"))
    message(FATAL_ERROR "UC_PLATFORMS: ${platform} cannot be built from ${UC_FMI_PLATFORM} (win64 can, from linux64)")
  endif()
  if(UC_BINARIES_ONLY)
    message(FATAL_ERROR "UC_PLATFORMS: a binaries-only tree builds its own platform only")
  endif()
  set(UC_WIN64_SUNDIALS_DIR ${CMAKE_SOURCE_DIR}/build/deps/win64/sundials CACHE PATH
      "SUNDIALS installed for win64 (scripts/setup builds it from Debian's source package)")
  if(NOT EXISTS ${UC_WIN64_SUNDIALS_DIR}/lib/cmake/sundials/SUNDIALSConfig.cmake)
    message(FATAL_ERROR "win64: no SUNDIALS for Windows in ${UC_WIN64_SUNDIALS_DIR}: run `bash scripts/setup "
                        "--platforms linux64,win64` (MinGW-w64, wine64 and SUNDIALS for the target)")
  endif()
  find_program(UC_MINGW_CXX x86_64-w64-mingw32-g++)
  if(NOT UC_MINGW_CXX)
    message(FATAL_ERROR "win64: no x86_64-w64-mingw32-g++: run `bash scripts/setup --platforms linux64,win64`")
  endif()
  include(ExternalProject)
  set(dir ${CMAKE_BINARY_DIR}/win64)
  set(dlls ${dir}/fmu/UnderwaterCable.dll ${dir}/fmu/fmi3/UnderwaterCable.dll ${dir}/tests/platform/uc_fmu_driver.exe ${dir}/tests/platform/uc_fmu_driver_fmi3.exe
           ${dir}/tests/platform/uc_load_cycles.exe ${dir}/tests/platform/uc_load_cycles_fmi3.exe)
  foreach(partner Vessel VesselRAO TowedBody)
    list(APPEND dlls ${dir}/fmu/partners/${partner}.dll)
  endforeach()
  ExternalProject_Add(uc_win64
    SOURCE_DIR ${CMAKE_SOURCE_DIR}
    BINARY_DIR ${dir}
    CMAKE_ARGS -DCMAKE_TOOLCHAIN_FILE=${CMAKE_SOURCE_DIR}/cmake/toolchains/mingw-w64-x86_64.cmake
               -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
               -DUC_BINARIES_ONLY=ON
               -DUC_PLATFORMS=win64
               -DUC_BUILD_TESTS=OFF
               -DSUNDIALS_DIR=${UC_WIN64_SUNDIALS_DIR}/lib/cmake/sundials
               -DEigen3_DIR=${Eigen3_DIR}
               -DPython3_EXECUTABLE=${Python3_EXECUTABLE}
    BUILD_ALWAYS ON
    INSTALL_COMMAND ""
    BUILD_BYPRODUCTS ${dlls}
    USES_TERMINAL_BUILD OFF)
  list(APPEND UC_FOREIGN_PLATFORMS win64)
  set(UC_FOREIGN_BINARY_DIR_win64 ${dir})
  list(APPEND UC_FOREIGN_DEPENDS uc_win64)
endforeach()
