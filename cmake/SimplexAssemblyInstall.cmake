# Installation and the package config, included by the top-level CMakeLists.txt:
#
#   cmake --install build --prefix P
#
# installs
#   P/include/simplex_assembly/<layer>/...     the headers, included as "optim/optim.h"
#   P/lib/libsa_<layer>.a (or .so)             sa::optim, sa::energies, sa::geometry, sa::frontends
#   P/lib/libsa_openmesh.so, libsa_vtk_io.so,  the plugins, loaded on first use
#     libsa_pictures.so                        (geometry/io/plugin_library.h)
#   P/bin/sa                                   the command
#   P/lib/cmake/SimplexAssembly/               SimplexAssemblyConfig.cmake, its version file, the
#                                              exported targets and FindCHOLMOD.cmake
# so that a project does
#
#   find_package(SimplexAssembly CONFIG REQUIRED)            # or COMPONENTS optim energies ...
#   target_link_libraries(app PRIVATE sa::optim)
#
# and gets the dependencies of the layers it asked for found (tests/consumer/ is such a project).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SA_INSTALL_INCLUDEDIR "${CMAKE_INSTALL_INCLUDEDIR}/simplex_assembly")
set(SA_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/SimplexAssembly")

set(sa_layers optim energies)
if(SA_BUILD_GEOMETRY)
    list(APPEND sa_layers geometry)
endif()
if(SA_BUILD_FRONTENDS)
    list(APPEND sa_layers frontends)
endif()

# Users compile against the headers as they were built: C++20, and the same instruction set when
# SA_NATIVE is on (Eigen's vectorization and the alignment of its fixed-size types must agree
# between the libraries and the program).
# (Inside this build, sa_build_flags gives the same to the project's own targets.)
target_compile_features(sa_optim INTERFACE $<INSTALL_INTERFACE:cxx_std_20>)
if(SA_NATIVE)
    target_compile_options(sa_optim INTERFACE $<INSTALL_INTERFACE:-march=native>)
endif()
target_include_directories(sa_optim PUBLIC $<INSTALL_INTERFACE:${SA_INSTALL_INCLUDEDIR}>)

set(sa_exported_targets "")
foreach(layer IN LISTS sa_layers)
    set_target_properties(sa_${layer} PROPERTIES EXPORT_NAME ${layer})
    list(APPEND sa_exported_targets sa_${layer})
endforeach()
# Linked privately by the layers: a static library's private dependencies are part of its link
# interface, so they are exported too, under names that say they are not for direct use.
set_target_properties(sa_build_flags PROPERTIES EXPORT_NAME detail_build_flags)
set_target_properties(sa_cholmod PROPERTIES EXPORT_NAME detail_cholmod)
list(APPEND sa_exported_targets sa_build_flags sa_cholmod)
if(SA_BUILD_GEOMETRY)
    set_target_properties(sa_file_support PROPERTIES EXPORT_NAME detail_file_support)
    list(APPEND sa_exported_targets sa_file_support)
endif()

# Shared libraries and the installed command find the libraries beside them.
if(BUILD_SHARED_LIBS)
    foreach(layer IN LISTS sa_layers)
        set_target_properties(sa_${layer} PROPERTIES INSTALL_RPATH "$ORIGIN")
    endforeach()
endif()

install(TARGETS ${sa_exported_targets} EXPORT SimplexAssemblyTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(plugin sa_openmesh sa_vtk_io sa_pictures)
    if(TARGET ${plugin})
        install(TARGETS ${plugin} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
    endif()
endforeach()
if(TARGET sa)
    set_target_properties(sa PROPERTIES INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
    install(TARGETS sa RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

# The headers of each layer built, without those of the command and of the plugins' insides
# (which include OpenMesh, VTK or Xlib).
foreach(layer IN LISTS sa_layers)
    install(DIRECTORY ${PROJECT_SOURCE_DIR}/${layer}/ DESTINATION ${SA_INSTALL_INCLUDEDIR}/${layer}
            FILES_MATCHING PATTERN "*.h"
            PATTERN "cli" EXCLUDE
            PATTERN "openmesh_plugin.h" EXCLUDE
            PATTERN "picture_plugin.h" EXCLUDE
            PATTERN "vtk_io_plugin.h" EXCLUDE
            PATTERN "openmesh_traits.h" EXCLUDE
            PATTERN "vtk_capture.h" EXCLUDE
            PATTERN "vtk_scene.h" EXCLUDE
            PATTERN "x_display.h" EXCLUDE)
endforeach()

install(EXPORT SimplexAssemblyTargets NAMESPACE sa:: DESTINATION ${SA_INSTALL_CMAKEDIR}
        FILE SimplexAssemblyTargets.cmake)
# What the config needs to know about this build.
set(SA_PACKAGE_LAYERS ${sa_layers})
set(SA_PACKAGE_STATIC OFF)
if(NOT BUILD_SHARED_LIBS)
    set(SA_PACKAGE_STATIC ON)
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/SimplexAssemblyConfig.cmake.in
    ${PROJECT_BINARY_DIR}/SimplexAssemblyConfig.cmake
    INSTALL_DESTINATION ${SA_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/SimplexAssemblyConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/SimplexAssemblyConfig.cmake
              ${PROJECT_BINARY_DIR}/SimplexAssemblyConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/FindCHOLMOD.cmake
        DESTINATION ${SA_INSTALL_CMAKEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
