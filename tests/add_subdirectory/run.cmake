# Configures the consumer (which does add_subdirectory(PENDEPTH_DIR)) with an empty
# CMAKE_BUILD_TYPE, builds it and runs it. Variables: PENDEPTH_DIR, SOURCE_DIR, WORK_DIR,
# GENERATOR, CXX_COMPILER, CXX_LAUNCHER (may be empty: passed on so ccache serves reruns).
file(REMOVE_RECURSE ${WORK_DIR})
set(args -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=
         -DPENDEPTH_SOURCE_DIR=${PENDEPTH_DIR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
if(CXX_LAUNCHER)
  list(APPEND args -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
execute_process(COMMAND ${CMAKE_COMMAND} ${args} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configure of the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build --target consumer RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "build of the consumer failed: ${rc}")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(rc)
  message(FATAL_ERROR "consumer returned ${rc}: ${out}")
endif()
