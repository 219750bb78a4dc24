# Finds SuiteSparse CHOLMOD, which Debian ships without a CMake config or pkg-config file.
# Defines CHOLMOD_FOUND and the imported targets
#   CHOLMOD::CHOLMOD  the shared libraries (their BLAS is the one Debian's alternatives choose);
#   CHOLMOD::static   when the archives are installed (libsuitesparse-dev, libopenblas-dev):
#                     CHOLMOD, its orderings and OpenBLAS linked into the executable, METIS,
#                     libgomp and libgfortran shared (CHOLMOD_STATIC_FOUND).
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY cholmod)
find_library(CHOLMOD_AMD_LIBRARY amd)
find_library(CHOLMOD_COLAMD_LIBRARY colamd)
find_library(CHOLMOD_CONFIG_LIBRARY suitesparseconfig)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD
    REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR CHOLMOD_AMD_LIBRARY
                  CHOLMOD_COLAMD_LIBRARY CHOLMOD_CONFIG_LIBRARY)

if(CHOLMOD_FOUND AND NOT TARGET CHOLMOD::CHOLMOD)
    add_library(CHOLMOD::CHOLMOD UNKNOWN IMPORTED)
    set_target_properties(CHOLMOD::CHOLMOD PROPERTIES
        IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES
            "${CHOLMOD_AMD_LIBRARY};${CHOLMOD_COLAMD_LIBRARY};${CHOLMOD_CONFIG_LIBRARY}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY CHOLMOD_AMD_LIBRARY
                 CHOLMOD_COLAMD_LIBRARY CHOLMOD_CONFIG_LIBRARY)

# The archives, in link order: each one's undefined symbols come from those after it.
set(cholmod_static_names cholmod ccolamd camd colamd amd suitesparseconfig openblas)
set(cholmod_static_libraries "")
set(CHOLMOD_STATIC_FOUND ${CHOLMOD_FOUND})
foreach(name IN LISTS cholmod_static_names)
    find_library(CHOLMOD_STATIC_${name} lib${name}.a)
    mark_as_advanced(CHOLMOD_STATIC_${name})
    if(CHOLMOD_STATIC_${name})
        list(APPEND cholmod_static_libraries "${CHOLMOD_STATIC_${name}}")
    else()
        set(CHOLMOD_STATIC_FOUND FALSE)
    endif()
endforeach()
find_library(CHOLMOD_METIS_LIBRARY NAMES metis libmetis.so.5)
find_library(CHOLMOD_GFORTRAN_LIBRARY NAMES gfortran libgfortran.so.5)
find_library(CHOLMOD_GOMP_LIBRARY NAMES gomp libgomp.so.1)
mark_as_advanced(CHOLMOD_METIS_LIBRARY CHOLMOD_GFORTRAN_LIBRARY CHOLMOD_GOMP_LIBRARY)
if(NOT CHOLMOD_METIS_LIBRARY OR NOT CHOLMOD_GFORTRAN_LIBRARY OR NOT CHOLMOD_GOMP_LIBRARY)
    set(CHOLMOD_STATIC_FOUND FALSE)
endif()

if(CHOLMOD_STATIC_FOUND AND NOT TARGET CHOLMOD::static)
    find_package(Threads REQUIRED)
    add_library(CHOLMOD::static INTERFACE IMPORTED)
    set_target_properties(CHOLMOD::static PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES
            "${cholmod_static_libraries};${CHOLMOD_METIS_LIBRARY};${CHOLMOD_GFORTRAN_LIBRARY};${CHOLMOD_GOMP_LIBRARY};Threads::Threads;m")
endif()
