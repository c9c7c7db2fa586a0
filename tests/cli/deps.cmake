# End-to-end tests run the built `pendepth` binary: build it first and pass its path.
if(NOT TARGET pendepth-cli)
  message(FATAL_ERROR "tests/cli needs the command-line tool: configure with PENDEPTH_BUILD_CLI=ON")
endif()
add_dependencies(${target} pendepth-cli)
target_compile_definitions(${target} PRIVATE PENDEPTH_CLI="$<TARGET_FILE:pendepth-cli>")
