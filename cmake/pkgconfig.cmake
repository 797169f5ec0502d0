# conformesh.pc for `pkg-config --cflags --libs conformesh` (docs/contributing.md, README): the three static libraries
# and every library they link, as the CMake package's link interface has them. Included at the end of the top-level
# CMakeLists.txt, after the libraries' folders found their dependencies (cache variables are visible here; imported
# targets and plain variables of a subfolder are not, so OpenMP is looked up again).
# Ceres: Debian ships libceres.a and libceres.so; -lceres takes the shared library, which brings glog, gflags,
# SuiteSparse and BLAS itself (the static archive would need them all listed). glog is named too: Ceres' headers
# expand glog's CHECK macros into our own objects, which then call glog directly (seen once the unity build emitted
# google::base::CheckOpMessageBuilder::NewString out of line; the linker takes no symbol through libceres's own needs).
find_package(OpenMP REQUIRED)
set(_pc_libs -lceres -lglog ${GeographicLib_LIBRARIES} ${CHOLMOD_LIBRARY} ${SCOTCH_LIBRARY}
             ${SCOTCH_ERR_LIBRARY} ${HDF5_C_LIBRARY})
if(CONFORMESH_WITH_MPI)
  list(APPEND _pc_libs ${MPI_CXX_LIBRARIES})
endif()
list(APPEND _pc_libs ${OpenMP_CXX_FLAGS} -pthread)
list(JOIN _pc_libs " " CONFORMESH_PC_LIBS)
# Boost and nlohmann-json are header-only in /usr/include; GeographicLib's headers are there too.
set(CONFORMESH_PC_CFLAGS "")
foreach(dir ${GeographicLib_INCLUDE_DIRS})
  if(NOT dir STREQUAL "/usr/include")
    string(APPEND CONFORMESH_PC_CFLAGS " -I${dir}")
  endif()
endforeach()
configure_file(${CMAKE_CURRENT_LIST_DIR}/conformesh.pc.in ${CMAKE_CURRENT_BINARY_DIR}/conformesh.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/conformesh.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
