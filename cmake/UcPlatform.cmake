# The FMI platform this tree builds for and how its FMU binaries link (docs/platforms.md).
#   UC_FMI_PLATFORM         linux64 or win64: the folder under binaries/ in the FMU
#   UC_FMU_LIBRARY_SUFFIX   .so or .dll
#   uc_fmu_link_options(T)  a self-contained FMU library: C and C++ runtimes linked statically, nothing but
#                           fmi2* exported, unresolved symbols an error at link time
if(CMAKE_SIZEOF_VOID_P EQUAL 8 AND CMAKE_SYSTEM_NAME STREQUAL "Linux")
  set(UC_FMI_PLATFORM linux64)
elseif(CMAKE_SIZEOF_VOID_P EQUAL 8 AND CMAKE_SYSTEM_NAME STREQUAL "Windows")
  set(UC_FMI_PLATFORM win64)
else()
  message(FATAL_ERROR "UnderwaterCable builds for linux64 and win64, not for ${CMAKE_SYSTEM_NAME} with "
                      "${CMAKE_SIZEOF_VOID_P}-byte pointers")
endif()
set(UC_FMU_LIBRARY_SUFFIX ${CMAKE_SHARED_LIBRARY_SUFFIX})

if(MINGW)
  # MinGW-w64's own printf/scanf family (C99: %zu, %lld, correctly rounded %g) instead of msvcrt.dll's,
  # so the FMU formats its log messages as on Linux; libstdc++ selects them for C++ already.
  add_compile_definitions(__USE_MINGW_ANSI_STDIO=1)
endif()

function(uc_fmu_link_options target export_map)
  if(WIN32)
    # PE exports are the functions marked dllexport (FMI2_Export): only fmi2*. -static: no libgcc_s,
    # libstdc++ or libwinpthread DLL beside the FMU, only Windows' own KERNEL32.dll and msvcrt.dll.
    target_link_options(${target} PRIVATE -static -static-libgcc -static-libstdc++ -Wl,--exclude-libs,ALL
                        -Wl,--no-undefined -s)
  else()
    target_link_options(${target} PRIVATE -Wl,--version-script=${export_map} -Wl,--exclude-libs,ALL -Wl,-z,defs
                        -static-libstdc++ -static-libgcc)
    set_target_properties(${target} PROPERTIES LINK_DEPENDS ${export_map})
  endif()
endfunction()
