# simcore's folders are its layers, lowest first: math, parallel (the task pool, which knows no
# physics), then the headers at the root (settings, which every stage reads), shapes, collision,
# dynamics, world, io. A file may include its own layer or a lower one, never a higher one.
# Run by ctest: cmake -DSOURCE_DIR=<repo> -P check_layers.cmake
set(layers math parallel . shapes collision dynamics world io)
function(layer_rank path out)  # path relative to simcore/
    string(FIND "${path}" "/" slash)
    if(slash EQUAL -1)
        set(folder ".")
    else()
        string(SUBSTRING "${path}" 0 ${slash} folder)
    endif()
    list(FIND layers "${folder}" rank)
    set(${out} ${rank} PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE files RELATIVE "${SOURCE_DIR}/simcore" "${SOURCE_DIR}/simcore/*.h" "${SOURCE_DIR}/simcore/*.cpp")
set(violations "")
foreach(file IN LISTS files)
    layer_rank("${file}" own)
    file(STRINGS "${SOURCE_DIR}/simcore/${file}" includes REGEX "^#include \"simcore/")
    foreach(line IN LISTS includes)
        string(REGEX REPLACE "^#include \"simcore/([^\"]+)\".*" "\\1" included "${line}")
        layer_rank("${included}" theirs)
        if(theirs GREATER own)
            string(APPEND violations "\n  simcore/${file} includes simcore/${included}")
        endif()
    endforeach()
endforeach()
if(violations)
    message(FATAL_ERROR "a lower simcore layer includes a higher one:${violations}")
endif()
list(LENGTH files count)
message(STATUS "simcore layers: ${count} files, no upward include")
