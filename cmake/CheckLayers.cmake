# The layering rule of common/: a file of layer L includes only L's own headers and those of
# the layers L declares in mcrt_layer(L DEPENDS ...). Any other #include "layer/..." is an
# error naming the file, the line and what L may include.
#
# Used two ways:
#   - from common/CMakeLists.txt at configure time: mcrt_check_layers(<common folder>);
#   - as a script (the test `layering`):
#       cmake -DROOT=<folder> -DRULES="core:|geometry:core|..." -P cmake/CheckLayers.cmake

if(CMAKE_SCRIPT_MODE_FILE)
  cmake_policy(VERSION 3.22)
endif()

# Checks every .hpp/.cpp below ROOT/<layer>/ against RULES, a list of "layer:dep,dep" items.
function(mcrt_check_layer_rules root rules)
  set(layers "")
  foreach(rule IN LISTS rules)
    string(REPLACE ":" ";" parts "${rule}")
    list(GET parts 0 layer)
    list(APPEND layers ${layer})
  endforeach()
  set(errors "")
  foreach(rule IN LISTS rules)
    string(REGEX REPLACE ":.*" "" layer "${rule}")
    string(REGEX REPLACE "^[^:]*:" "" allowed "${rule}")
    string(REPLACE "," ";" allowed "${allowed}")
    list(APPEND allowed ${layer})
    file(GLOB_RECURSE files ${root}/${layer}/*.hpp ${root}/${layer}/*.cpp)
    foreach(file IN LISTS files)
      file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]+\"[^/\"]+/")
      foreach(line IN LISTS includes)
        string(REGEX REPLACE "^[^\"]*\"([^/\"]+)/.*" "\\1" target "${line}")
        if(target IN_LIST layers AND NOT target IN_LIST allowed)
          file(RELATIVE_PATH relative ${root} ${file})
          string(REPLACE ";" ", " allowed_text "${allowed}")
          list(APPEND errors "${relative}: ${line}: layer '${layer}' may include only ${allowed_text}")
        endif()
      endforeach()
    endforeach()
  endforeach()
  if(errors)
    string(REPLACE ";" "\n  " text "${errors}")
    message(FATAL_ERROR "layering violated:\n  ${text}")
  endif()
endfunction()

# The rules as mcrt_layer() recorded them, as one string for the script mode.
function(mcrt_layer_rules out)
  set(rules "")
  foreach(layer IN LISTS MCRT_LAYERS)
    string(REPLACE ";" "," depends "${MCRT_LAYER_DEPENDS_${layer}}")
    list(APPEND rules "${layer}:${depends}")
  endforeach()
  string(REPLACE ";" "|" rules "${rules}")
  set(${out} "${rules}" PARENT_SCOPE)
endfunction()

function(mcrt_check_layers root)
  mcrt_layer_rules(rules)
  string(REPLACE "|" ";" rules "${rules}")
  mcrt_check_layer_rules(${root} "${rules}")
endfunction()

if(CMAKE_SCRIPT_MODE_FILE AND DEFINED ROOT)
  string(REPLACE "|" ";" rule_list "${RULES}")
  mcrt_check_layer_rules(${ROOT} "${rule_list}")
  message(STATUS "layering: every include of ${ROOT} follows its layer's rules")
endif()
