# Building against Debian's FreeCAD (0.20.2 on Debian 12, 1.0 on Debian 13) without its C++
# headers package (Debian has none): the headers come from Debian's source package of the same
# release (FREECAD_SOURCE_DIR, unpacked by setup/featurelines), the libraries from the installed
# binary packages. Nothing of FreeCAD is compiled here except the *Py.h headers FreeCAD generates
# from its .xml models.
#
# Defines the interface targets FreeCAD::App (Base, App, Part, Points) and FreeCAD::Gui
# (adds Gui, PartGui, Qt5 widgets and Coin3D), FREECAD_LIB_DIR and FREECAD_VERSION (e.g. 0.20.2,
# 1.0.0). The code sees the version as FEATURELINES_FREECAD_VERSION (major * 100 + minor: 20 for
# 0.20, 100 for 1.0); App/FreeCADCompat.h keeps the API differences in one place.

set(FREECAD_SOURCE_DIR "" CACHE PATH "Unpacked Debian FreeCAD source (apt-get source freecad)")
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

# The headers' version, from the source tree's top CMakeLists.txt (PACKAGE_VERSION_MAJOR ...).
file(STRINGS "${FREECAD_SOURCE_DIR}/CMakeLists.txt" version_lines
     REGEX "^set\\(PACKAGE_VERSION_(MAJOR|MINOR|PATCH) \"[0-9]+\"")
foreach(part MAJOR MINOR PATCH)
    string(REGEX MATCH "PACKAGE_VERSION_${part} \"([0-9]+)\"" found "${version_lines}")
    if(NOT found)
        message(FATAL_ERROR "No PACKAGE_VERSION_${part} in ${FREECAD_SOURCE_DIR}/CMakeLists.txt")
    endif()
    set(FREECAD_VERSION_${part} "${CMAKE_MATCH_1}")
endforeach()
set(FREECAD_VERSION "${FREECAD_VERSION_MAJOR}.${FREECAD_VERSION_MINOR}.${FREECAD_VERSION_PATCH}")
math(EXPR FEATURELINES_FREECAD_VERSION "${FREECAD_VERSION_MAJOR} * 100 + ${FREECAD_VERSION_MINOR}")
if(FEATURELINES_FREECAD_VERSION LESS 20)
    message(FATAL_ERROR "FreeCAD ${FREECAD_VERSION} is too old: FeatureLines needs 0.20.2 or later")
endif()
message(STATUS "FreeCAD ${FREECAD_VERSION} headers from ${FREECAD_SOURCE_DIR}")

# FreeCAD's libraries name the Python and Boost they were built with (3.11 and 1.74 on Debian 12,
# 3.13 and 1.83 on Debian 13): the module must use the same. The interpreter must be Debian's,
# not a pyenv one first on PATH; Boost's signals2 objects are part of FreeCAD's class layouts.
file(STRINGS "${FREECAD_LIB_DIR}/libFreeCADBase.so" needed REGEX "^lib(python3\\.[0-9]+|boost_[a-z_]+)\\.so")
string(REGEX MATCH "libpython(3\\.[0-9]+)\\.so" found "${needed}")
if(NOT found)
    message(FATAL_ERROR "${FREECAD_LIB_DIR}/libFreeCADBase.so names no libpython3.X")
endif()
set(FREECAD_PYTHON_VERSION "${CMAKE_MATCH_1}")
string(REGEX MATCH "libboost_[a-z_]+\\.so\\.([0-9]+\\.[0-9]+)" found "${needed}")
if(NOT found)
    message(FATAL_ERROR "${FREECAD_LIB_DIR}/libFreeCADBase.so names no Boost library")
endif()
set(FREECAD_BOOST_VERSION "${CMAKE_MATCH_1}")
find_package(Python3 ${FREECAD_PYTHON_VERSION} EXACT REQUIRED COMPONENTS Interpreter Development)
find_package(Boost ${FREECAD_BOOST_VERSION} EXACT REQUIRED)
find_package(OpenCASCADE CONFIG REQUIRED)
find_package(XercesC REQUIRED)
find_package(Qt5 REQUIRED COMPONENTS Core)
set(freecad_extra_libs "")
if(FEATURELINES_FREECAD_VERSION GREATER_EQUAL 100)
    # FreeCAD 1.0: Base/Console.h formats with fmt.
    find_package(fmt REQUIRED)
    list(APPEND freecad_extra_libs fmt::fmt)
endif()

# Generate the *Py.h headers once per source tree, mirroring src/ so that FreeCAD's own
# includes (<App/DocumentObjectPy.h>, <Mod/Part/App/TopoShapePy.h>) resolve.
set(FREECAD_GENERATED_DIR "${CMAKE_BINARY_DIR}/freecad-generated")
set(stamp "${FREECAD_GENERATED_DIR}/.stamp")
set(stamp_text "${FREECAD_SOURCE_DIR}\n")
if(EXISTS "${stamp}")
    file(READ "${stamp}" old_stamp)
    if(NOT old_stamp STREQUAL stamp_text)
        file(REMOVE_RECURSE "${FREECAD_GENERATED_DIR}")
    endif()
endif()
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
    file(WRITE "${stamp}" "${stamp_text}")
endif()

# FreeCAD 1.0: FCGlobal.h includes <QtCore.h>, written by FreeCAD's configure step from this
# template; Qt 5.15 has Q_DISABLE_COPY_MOVE.
if(EXISTS "${FREECAD_SOURCE_DIR}/src/QtCore.h.cmake")
    set(HAVE_Q_DISABLE_COPY_MOVE ON)
    configure_file("${FREECAD_SOURCE_DIR}/src/QtCore.h.cmake" "${FREECAD_GENERATED_DIR}/QtCore.h")
endif()

add_library(FreeCAD_App INTERFACE)
add_library(FreeCAD::App ALIAS FreeCAD_App)
target_include_directories(FreeCAD_App SYSTEM INTERFACE
    "${FREECAD_GENERATED_DIR}" "${FREECAD_SOURCE_DIR}/src" ${OpenCASCADE_INCLUDE_DIR}
    ${Python3_INCLUDE_DIRS} ${Boost_INCLUDE_DIRS} ${XercesC_INCLUDE_DIRS})
target_compile_definitions(FreeCAD_App INTERFACE _OCC64
    FEATURELINES_FREECAD_VERSION=${FEATURELINES_FREECAD_VERSION})
# FreeCAD's headers pull in <strstream> (zipios++): silence that one deprecation notice.
target_compile_options(FreeCAD_App INTERFACE -Wno-deprecated)
target_link_libraries(FreeCAD_App INTERFACE
    "${FREECAD_LIB_DIR}/libFreeCADBase.so" "${FREECAD_LIB_DIR}/libFreeCADApp.so"
    "${FREECAD_LIB_DIR}/Part.so" "${FREECAD_LIB_DIR}/Points.so"
    Python3::Python Qt5::Core XercesC::XercesC ${freecad_extra_libs}
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
