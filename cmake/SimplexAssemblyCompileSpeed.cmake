# How the project's own targets are compiled quickly, included by the top-level CMakeLists.txt
# (docs/measurements.md, "Build time", measures each choice):
#
# - sa_precompile_headers(target [TBB] [GTEST]): the standard, Eigen and (when asked) TBB and
#   GoogleTest headers that nearly every unit of `target` includes are parsed once per
#   target, into a precompiled header, instead of once per unit. -DSA_PRECOMPILED_HEADERS=OFF
#   turns them off; the sources include what they use either way, so that they build without
#   them (and the installed headers compile in a user's project, which has none).
# - ccache, when it is installed and no compiler launcher is set, for a developer's warm
#   rebuilds (CI builds from scratch and does not install it).

option(SA_PRECOMPILED_HEADERS "Precompile the common third-party headers of each target" ON)

if(NOT CMAKE_CXX_COMPILER_LAUNCHER)
    find_program(SA_CCACHE ccache)
    mark_as_advanced(SA_CCACHE)
    if(SA_CCACHE)
        # Precompiled headers need these (ccache's manual, "Precompiled headers").
        set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env
            "CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime"
            ${SA_CCACHE})
        message(STATUS "ccache: ${SA_CCACHE}")
    endif()
endif()

set(sa_pch_headers
    <algorithm> <array> <cmath> <cstdint> <functional> <limits> <memory> <sstream> <string>
    <utility> <vector>
    <Eigen/Core> <Eigen/LU>)

function(sa_precompile_headers target)
    if(NOT SA_PRECOMPILED_HEADERS)
        return()
    endif()
    cmake_parse_arguments(arg "TBB;GTEST" "" "" ${ARGN})
    set(headers ${sa_pch_headers})
    if(arg_TBB)
        list(APPEND headers <tbb/blocked_range.h> <tbb/parallel_for.h> <tbb/parallel_reduce.h>)
    endif()
    if(arg_GTEST)
        list(APPEND headers <gtest/gtest.h>)
    endif()
    target_precompile_headers(${target} PRIVATE ${headers})
endfunction()
