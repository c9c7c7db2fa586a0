# The soak reads nothing from disk, but tests/polygon2/shapes.hpp (its 2D shape generators)
# includes nlohmann-json for the nesting-instance reader.
find_package(nlohmann_json REQUIRED)
target_link_libraries(${target} PRIVATE nlohmann_json::nlohmann_json)
