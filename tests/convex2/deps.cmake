# The brute-force oracle (tests/convex2/brute_force.hpp) uses GMP's C++ rationals.
target_link_libraries(${target} PRIVATE PkgConfig::GMPXX)
