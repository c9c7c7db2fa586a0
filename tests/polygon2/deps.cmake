# The exact oracle (tests/polygon2/oracle_cgal.cpp) uses CGAL's exact kernel; the exactness
# checks use GMP rationals.
find_package(CGAL REQUIRED)
find_package(nlohmann_json REQUIRED)
target_link_libraries(${target} PRIVATE CGAL::CGAL PkgConfig::GMPXX nlohmann_json::nlohmann_json gmp mpfr)
