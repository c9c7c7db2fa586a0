# The fuzz targets' code (tests/fuzz/fuzz_*.cpp), compiled as plain functions named after the
# targets, replays the seed corpus in every build (GCC, the ASan stage) without libFuzzer.
file(GLOB PENDEPTH_FUZZ_REPLAY_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tests/fuzz/fuzz_*.cpp)
target_sources(${target} PRIVATE ${PENDEPTH_FUZZ_REPLAY_SOURCES})
target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/tests/fuzz)
target_compile_definitions(${target} PRIVATE PENDEPTH_FUZZ_REPLAY
                           PENDEPTH_FUZZ_CORPUS="${PROJECT_SOURCE_DIR}/tests/fuzz/corpus")
