# Building against Debian's FreeCAD 0.20.2 without its C++ headers package (Debian has none):
# the headers come from Debian's source package of the same release (FREECAD_SOURCE_DIR,
# unpacked by setup/featurelines), the libraries from the installed binary packages. Nothing
# of FreeCAD is compiled here except the *Py.h headers FreeCAD generates from its .xml models.
#
# Defines the interface targets FreeCAD::App (Base, App, Part, Points) and FreeCAD::Gui
# (adds Gui, PartGui, Qt5 widgets and Coin3D), and FREECAD_LIB_DIR.

set(FREECAD_SOURCE_DIR "" CACHE PATH "Unpacked Debian FreeCAD 0.20.2 source (apt-get source freecad)")
set(FREECAD_LIB_DIR "/usr/lib/freecad-python3/lib" CACHE PATH "Debian's FreeCAD libraries")
if(NOT EXISTS "${FREECAD_SOURCE_DIR}/src/App/Application.h")
    message(FATAL_ERROR "FREECAD_SOURCE_DIR='${FREECAD_SOURCE_DIR}' is not a FreeCAD source tree; "
                        "run setup/featurelines, or configure with -DFEATURELINES_CORE_ONLY=ON")
endif()
foreach(lib libFreeCADBase.so libFreeCADApp.so Part.so Points.so)
    if(NOT EXISTS "${FREECAD_LIB_DIR}/${lib}")
        message(FATAL_ERROR "${FREECAD_LIB_DIR}/${lib} is missing: install Debian's freecad package")
    endif()
endforeach()

# FreeCAD links libpython3.11: the interpreter must be Debian's, not a pyenv one first on PATH.
find_package(Python3 3.11 EXACT REQUIRED COMPONENTS Interpreter Development)
# signals2 objects are part of FreeCAD's class layouts: the Boost FreeCAD was built with.
find_package(Boost 1.74 EXACT REQUIRED)
find_package(OpenCASCADE CONFIG REQUIRED)
find_package(XercesC REQUIRED)
find_package(Qt5 REQUIRED COMPONENTS Core)

# Generate the *Py.h headers once per source tree, mirroring src/ so that FreeCAD's own
# includes (<App/DocumentObjectPy.h>, <Mod/Part/App/TopoShapePy.h>) resolve.
set(FREECAD_GENERATED_DIR "${CMAKE_BINARY_DIR}/freecad-generated")
set(stamp "${FREECAD_GENERATED_DIR}/.stamp")
if(NOT EXISTS "${stamp}")
    message(STATUS "Generating FreeCAD's *Py.h headers from ${FREECAD_SOURCE_DIR}")
    foreach(part Base App Gui Mod/Part/App Mod/Points/App)
        file(GLOB_RECURSE models RELATIVE "${FREECAD_SOURCE_DIR}/src/${part}"
             "${FREECAD_SOURCE_DIR}/src/${part}/*Py.xml")
        foreach(model ${models})
            get_filename_component(subdir "${model}" DIRECTORY)
            get_filename_component(xmldir "${FREECAD_SOURCE_DIR}/src/${part}/${model}" DIRECTORY)
            set(out "${FREECAD_GENERATED_DIR}/${part}")
            if(subdir)
                set(out "${out}/${subdir}")
            endif()
            file(MAKE_DIRECTORY "${out}")
            get_filename_component(name "${model}" NAME)
            execute_process(
                COMMAND "${Python3_EXECUTABLE}" "${FREECAD_SOURCE_DIR}/src/Tools/generate.py"
                        --outputPath "${out}" "${name}"
                WORKING_DIRECTORY "${xmldir}" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
            if(NOT rc EQUAL 0)
                message(FATAL_ERROR "generate.py failed on ${part}/${model}: ${err}")
            endif()
        endforeach()
    endforeach()
    file(WRITE "${stamp}" "${FREECAD_SOURCE_DIR}\n")
endif()

add_library(FreeCAD_App INTERFACE)
add_library(FreeCAD::App ALIAS FreeCAD_App)
target_include_directories(FreeCAD_App SYSTEM INTERFACE
    "${FREECAD_GENERATED_DIR}" "${FREECAD_SOURCE_DIR}/src" ${OpenCASCADE_INCLUDE_DIR}
    ${Python3_INCLUDE_DIRS} ${Boost_INCLUDE_DIRS} ${XercesC_INCLUDE_DIRS})
target_compile_definitions(FreeCAD_App INTERFACE _OCC64)
# FreeCAD 0.20 headers pull in <strstream> (zipios++): silence that one deprecation notice.
target_compile_options(FreeCAD_App INTERFACE -Wno-deprecated)
target_link_libraries(FreeCAD_App INTERFACE
    "${FREECAD_LIB_DIR}/libFreeCADBase.so" "${FREECAD_LIB_DIR}/libFreeCADApp.so"
    "${FREECAD_LIB_DIR}/Part.so" "${FREECAD_LIB_DIR}/Points.so"
    Python3::Python Qt5::Core XercesC::XercesC
    TKernel TKMath TKG2d TKG3d TKGeomBase TKBRep TKGeomAlgo TKTopAlgo)

if(NOT FEATURELINES_APP_ONLY)
    find_package(Qt5 REQUIRED COMPONENTS Widgets OpenGL Svg)
    find_package(Coin CONFIG REQUIRED)
    add_library(FreeCAD_Gui INTERFACE)
    add_library(FreeCAD::Gui ALIAS FreeCAD_Gui)
    # Gui/View3DInventor.h includes <QtOpenGL.h>, which FreeCAD's own configure step writes
    # from this template (plain includes and typedefs, nothing to substitute).
    configure_file("${FREECAD_SOURCE_DIR}/src/QtOpenGL.h.cmake"
                   "${FREECAD_GENERATED_DIR}/QtOpenGL.h" COPYONLY)
    target_link_libraries(FreeCAD_Gui INTERFACE FreeCAD::App
        "${FREECAD_LIB_DIR}/libFreeCADGui.so" "${FREECAD_LIB_DIR}/PartGui.so"
        "${FREECAD_LIB_DIR}/PointsGui.so"
        Qt5::Widgets Qt5::OpenGL Qt5::Svg Coin::Coin)
endif()
