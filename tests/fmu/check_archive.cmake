# cmake -DFMU=<path to UnderwaterCable.fmu> -P check_archive.cmake
# The FMU zip holds modelDescription.xml at the root and binaries/linux64/UnderwaterCable.so, with relative
# forward-slash paths and no "./" or "/" prefixes, and its documentation with the licences.
if(NOT EXISTS "${FMU}")
  message(FATAL_ERROR "no FMU at '${FMU}'")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E tar tf "${FMU}" OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cannot list ${FMU}")
endif()
string(REPLACE "\n" ";" entries "${listing}")
foreach(required modelDescription.xml binaries/linux64/UnderwaterCable.so documentation/index.html
                 documentation/LICENSE.txt documentation/THIRD_PARTY.txt)
  list(FIND entries "${required}" index)
  if(index LESS 0)
    message(FATAL_ERROR "${FMU} lacks ${required}; it holds: ${listing}")
  endif()
endforeach()
foreach(entry IN LISTS entries)
  if(entry MATCHES "^(\\./|/)" OR entry MATCHES "\\\\")
    message(FATAL_ERROR "bad path in ${FMU}: '${entry}'")
  endif()
endforeach()
message(STATUS "${FMU}: ${listing}")
