# The motion tests read the nesting instances (JSON) of ../shared/data.
find_package(nlohmann_json REQUIRED)
target_link_libraries(${target} PRIVATE nlohmann_json::nlohmann_json)
# test_generalized3_mesh: GMP rationals for the exact displacement (tests/mesh3/mesh_gen.hpp).
target_link_libraries(${target} PRIVATE PkgConfig::GMPXX)
