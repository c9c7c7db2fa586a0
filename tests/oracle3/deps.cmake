# test_oracle3: the independent exact 3D oracle uses CGAL's Epeck kernel (GMP rationals) for the
# hull of all pairwise differences and MPFR for correctly rounded square roots. CGAL headers are
# confined to oracle3_cgal.cpp.
find_package(CGAL REQUIRED)
find_library(PENDEPTH_MPFR_LIBRARY mpfr REQUIRED)
target_link_libraries(${target} PRIVATE CGAL::CGAL PkgConfig::GMPXX ${PENDEPTH_MPFR_LIBRARY})
if(PENDEPTH_SANITIZE)
  # As in tests/oracle: UBSan's vptr check trips over CGAL's internal downcasts; only that check
  # is off, and only in the one file that includes CGAL.
  set_source_files_properties(${CMAKE_CURRENT_LIST_DIR}/oracle3_cgal.cpp PROPERTIES COMPILE_OPTIONS -fno-sanitize=vptr)
endif()
