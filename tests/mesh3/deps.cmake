# test_mesh3: CGAL (Epick) is the oracle for self-intersections (Polygon_mesh_processing) and for
# point-in-mesh (Side_of_triangle_mesh); GMP rationals for exact volumes; CGAL's exact Nef
# minkowski_sum_3 for the mesh pairs' σ_d (test_mesh_pair_nef.cpp). CGAL's sample meshes
# (libcgal-demo's data.tar.gz) are unpacked at configure time when the package is installed.
find_package(CGAL REQUIRED)
target_link_libraries(${target} PRIVATE CGAL::CGAL PkgConfig::GMPXX)
set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/oracle_cgal.cpp ${CMAKE_CURRENT_LIST_DIR}/test_mesh_pair_nef.cpp
                            ${CMAKE_CURRENT_LIST_DIR}/test_fine_lambda.cpp
                            PROPERTIES COMPILE_OPTIONS -frounding-math)
set(PENDEPTH_CGAL_DATA_TGZ /usr/share/doc/libcgal-demo/data.tar.gz)
if(EXISTS ${PENDEPTH_CGAL_DATA_TGZ})
  set(PENDEPTH_CGAL_DATA_DIR ${PROJECT_BINARY_DIR}/cgal_data)
  if(NOT EXISTS ${PENDEPTH_CGAL_DATA_DIR}/data/meshes)
    file(MAKE_DIRECTORY ${PENDEPTH_CGAL_DATA_DIR})
    execute_process(COMMAND tar xzf ${PENDEPTH_CGAL_DATA_TGZ} data/meshes WORKING_DIRECTORY ${PENDEPTH_CGAL_DATA_DIR})
  endif()
  target_compile_definitions(${target} PRIVATE PENDEPTH_CGAL_MESHES="${PENDEPTH_CGAL_DATA_DIR}/data/meshes")
else()
  message(STATUS "pendepth: libcgal-demo not installed: test_mesh3 runs without CGAL's sample meshes")
endif()
