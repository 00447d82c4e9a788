# Locates the Debian 12 packages piezocontact builds on. Each dependency becomes an imported target so
# that the library's link line stays readable: Eigen3::Eigen, piezocontact::suitesparse,
# piezocontact::mumps, piezocontact::gmsh.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)

find_path(UMFPACK_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(UMFPACK_LIBRARY umfpack REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(AMD_LIBRARY amd REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
if(NOT TARGET piezocontact::suitesparse)
  add_library(piezocontact::suitesparse INTERFACE IMPORTED)
  set_target_properties(piezocontact::suitesparse PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${UMFPACK_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${UMFPACK_LIBRARY};${CHOLMOD_LIBRARY};${AMD_LIBRARY};${SUITESPARSECONFIG_LIBRARY}")
endif()

find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
if(PIEZOCONTACT_MUMPS_MPI)
  find_package(MPI REQUIRED COMPONENTS C)
  find_library(DMUMPS_LIBRARY dmumps REQUIRED)
  find_library(MUMPS_COMMON_LIBRARY mumps_common REQUIRED)
  set(_mumps_libs "${DMUMPS_LIBRARY};${MUMPS_COMMON_LIBRARY};MPI::MPI_C")
  set(_mumps_includes "${MUMPS_INCLUDE_DIR}")
else()
  # The sequential build ships a stub mpi.h of its own in include/mumps_seq.
  find_path(MUMPS_SEQ_MPI_INCLUDE_DIR mpi.h PATHS /usr/include/mumps_seq NO_DEFAULT_PATH REQUIRED)
  find_library(DMUMPS_LIBRARY dmumps_seq REQUIRED)
  find_library(MUMPS_COMMON_LIBRARY mumps_common_seq REQUIRED)
  find_library(MUMPS_MPISEQ_LIBRARY mpiseq_seq REQUIRED)
  find_library(MUMPS_PORD_LIBRARY pord_seq REQUIRED)
  set(_mumps_libs "${DMUMPS_LIBRARY};${MUMPS_COMMON_LIBRARY};${MUMPS_PORD_LIBRARY};${MUMPS_MPISEQ_LIBRARY}")
  set(_mumps_includes "${MUMPS_INCLUDE_DIR};${MUMPS_SEQ_MPI_INCLUDE_DIR}")
endif()
if(NOT TARGET piezocontact::mumps)
  add_library(piezocontact::mumps INTERFACE IMPORTED)
  set_target_properties(piezocontact::mumps PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${_mumps_includes}"
    INTERFACE_LINK_LIBRARIES "${_mumps_libs}")
endif()

find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
if(NOT TARGET piezocontact::gmsh)
  add_library(piezocontact::gmsh INTERFACE IMPORTED)
  set_target_properties(piezocontact::gmsh PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${GMSH_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${GMSH_LIBRARY}")
endif()
