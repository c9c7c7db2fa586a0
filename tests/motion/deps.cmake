# The motion tests read the nesting instances (JSON) of ../shared/data.
find_package(nlohmann_json REQUIRED)
target_link_libraries(${target} PRIVATE nlohmann_json::nlohmann_json)
