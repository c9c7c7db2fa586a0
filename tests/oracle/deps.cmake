# test_oracle: exact references with CGAL's Epeck kernel (GMP rationals) and MPFR for rounding.
# CGAL headers are confined to exact_oracle.cpp.
find_package(CGAL REQUIRED)
find_library(PENDEPTH_MPFR_LIBRARY mpfr REQUIRED)
target_link_libraries(${target} PRIVATE CGAL::CGAL PkgConfig::GMPXX ${PENDEPTH_MPFR_LIBRARY})
if(PENDEPTH_SANITIZE)
  # CGAL 5.5's arrangement iterators (used by minkowski_sum_2) downcast DCEL records in a way
  # UBSan's vptr check rejects; that is CGAL's code, not ours, so only that check is off, and only
  # in the one file that includes CGAL.
  set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/exact_oracle.cpp PROPERTIES COMPILE_OPTIONS -fno-sanitize=vptr)
endif()
