# The editor's model layer (the interplay_model target: document, undo commands, file handling,
# scene actions, simulation controller) stands on Qt Core and Gui only, under the widgets. Fails if
#  - the target links Qt Widgets or a target built on it, directly or through another target
#    (seen as QT_WIDGETS_LIB among its compile definitions, which carry every linked target's), or
#  - a model source includes a header of a widgets module (<QWidget>, <QtWidgets/...>, ...) or an
#    app header outside the model (the viewport, the panels, the main window).
# Run by ctest: cmake -DFACTS=<file> -P check_model_layer.cmake, where FACTS sets model_source_dir,
# model_sources, model_links, model_definitions and qt_include_dirs (tests/CMakeLists.txt generates
# it from the target, and another for tests/data/model_layer/, a violation the check must catch).
cmake_minimum_required(VERSION 3.25)  # IN_LIST, list(TRANSFORM)
include("${FACTS}")
# The widgets modules' own header folders (QtWidgets, QtOpenGLWidgets, QtQuickWidgets), not Qt's
# include root, which holds every module.
set(widgets_include_dirs "")
foreach(dir IN LISTS qt_include_dirs)
    if(dir MATCHES "Widgets/?$")
        list(APPEND widgets_include_dirs "${dir}")
    endif()
endforeach()
list(REMOVE_DUPLICATES widgets_include_dirs)
if(NOT widgets_include_dirs)
    message(FATAL_ERROR "no Qt widgets header folder among ${qt_include_dirs}: the check would see nothing")
endif()
list(FILTER model_sources INCLUDE REGEX "\\.(h|cpp)$")  # not autogen's timestamps
list(TRANSFORM model_sources PREPEND "${model_source_dir}/" REGEX "^[^/]")

set(violations "")
foreach(definition IN LISTS model_definitions)
    if(definition STREQUAL "QT_WIDGETS_LIB")
        string(APPEND violations "\n  interplay_model links Qt Widgets (QT_WIDGETS_LIB comes with one of: ${model_links})")
    endif()
endforeach()
foreach(library IN LISTS model_links)
    if(library MATCHES "Widgets|^interplay_app$")
        string(APPEND violations "\n  interplay_model links ${library}")
    endif()
endforeach()

# The model's own headers, as its sources include them ("app/document/scene_document.h").
set(model_headers "")
foreach(source IN LISTS model_sources)
    if(source MATCHES "/app/(.+\\.h)$")
        list(APPEND model_headers "app/${CMAKE_MATCH_1}")
    endif()
endforeach()

foreach(source IN LISTS model_sources)
    file(STRINGS "${source}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS includes)
        string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]+)[>\"].*" "\\1" included "${line}")
        if(included MATCHES "^Qt[A-Za-z]*Widgets/")
            string(APPEND violations "\n  ${source} includes <${included}>")
        elseif(included MATCHES "^app/" AND NOT included IN_LIST model_headers)
            string(APPEND violations "\n  ${source} includes \"${included}\", which is above the model")
        else()
            foreach(dir IN LISTS widgets_include_dirs)
                if(EXISTS "${dir}/${included}" AND NOT IS_DIRECTORY "${dir}/${included}")
                    string(APPEND violations "\n  ${source} includes <${included}> (from ${dir})")
                endif()
            endforeach()
        endif()
    endforeach()
endforeach()

if(violations)
    message(FATAL_ERROR "the model layer depends on widgets:${violations}")
endif()
list(LENGTH model_sources count)
message(STATUS "model layer: ${count} files on Qt Core and Gui only")
