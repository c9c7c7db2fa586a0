# The exact oracle (tests/nonconvex2/oracle_cgal.cpp) uses CGAL's exact kernel (Epeck), its convex
# partition and reduced-convolution Minkowski sum.
find_package(CGAL REQUIRED)
find_package(nlohmann_json REQUIRED)
target_link_libraries(${target} PRIVATE CGAL::CGAL PkgConfig::GMPXX nlohmann_json::nlohmann_json gmp mpfr)
if(PENDEPTH_SANITIZE)
  # CGAL 5.5's arrangement iterators (minkowski_sum_2 in the oracle) downcast DCEL records in a way
  # UBSan's vptr check rejects; that is CGAL's code, so only that check is off, only in this file.
  set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/oracle_cgal.cpp PROPERTIES COMPILE_OPTIONS -fno-sanitize=vptr)
endif()
