# Fails unless the scenes A and B hold the same entries: the lines of
# both with comments, blank lines and trailing blanks removed. The scenario
# copies of params/ scenes carry a test header of their own, and must not
# drift from the scene a user runs.
#   cmake -DA=<scene.prm> -DB=<scene.prm> -P same_scene.cmake
function(scene_entries path result)
  file(STRINGS "${path}" lines)
  set(entries "")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "#.*$" "" line "${line}")
    string(STRIP "${line}" line)
    string(REGEX REPLACE "[ \t]+" " " line "${line}")
    if(NOT line STREQUAL "")
      list(APPEND entries "${line}")
    endif()
  endforeach()
  set(${result} "${entries}" PARENT_SCOPE)
endfunction()

scene_entries("${A}" entries_a)
scene_entries("${B}" entries_b)
if(NOT entries_a STREQUAL entries_b)
  list(LENGTH entries_a n_a)
  list(LENGTH entries_b n_b)
  set(first "")
  foreach(index RANGE 0 1000)
    if(index GREATER_EQUAL n_a OR index GREATER_EQUAL n_b)
      break()
    endif()
    list(GET entries_a ${index} line_a)
    list(GET entries_b ${index} line_b)
    if(NOT line_a STREQUAL line_b)
      set(first "first difference: '${line_a}' against '${line_b}'")
      break()
    endif()
  endforeach()
  message(FATAL_ERROR "${B} does not hold the entries of ${A} "
    "(${n_a} against ${n_b} entries; ${first}): copy the change over.")
endif()
