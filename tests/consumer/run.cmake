# Builds and runs an outside project that uses glint (CTest label `consumer`).
# -DKIND=find_package: install glint into a temporary prefix, then find_package(glint) from it,
#   for the consumer and for glint's own benchmarks.
# -DKIND=add_subdirectory: add glint's source tree as a subdirectory.
cmake_minimum_required(VERSION 3.16)

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${status}): ${command}")
  endif()
endfunction()

file(REMOVE_RECURSE "${WORK_DIR}")
set(consumer_source "${GLINT_SOURCE_DIR}/tests/consumer/${KIND}")
set(common -G "${GENERATOR}" -DCMAKE_CXX_COMPILER=${CXX} -DCMAKE_BUILD_TYPE=Release)
if(KIND STREQUAL "find_package")
  set(prefix "${WORK_DIR}/prefix")
  run(${CMAKE_COMMAND} ${common} -S "${GLINT_SOURCE_DIR}" -B "${WORK_DIR}/glint"
      -DCMAKE_INSTALL_PREFIX=${prefix}
      -DGLINT_BUILD_TESTS=OFF -DGLINT_BUILD_BENCH=OFF -DGLINT_BUILD_EXAMPLES=OFF -DGLINT_INSTALL=ON)
  run(${CMAKE_COMMAND} --install "${WORK_DIR}/glint")
  if(NOT EXISTS "${prefix}/share/glint/glsl/core.glsl")
    message(FATAL_ERROR "the kernel files were not installed to share/glint/glsl")
  endif()
  run(${CMAKE_COMMAND} ${common} -S "${consumer_source}" -B "${WORK_DIR}/consumer" -DCMAKE_PREFIX_PATH=${prefix})
  # The benchmarks build against the installed package too.
  run(${CMAKE_COMMAND} ${common} -S "${GLINT_SOURCE_DIR}/bench" -B "${WORK_DIR}/bench" -DCMAKE_PREFIX_PATH=${prefix})
  run(${CMAKE_COMMAND} --build "${WORK_DIR}/bench" --target glint_bench_core)
  run("${WORK_DIR}/bench/glint_bench_core" --benchmark_filter=pcg3d --benchmark_min_time=0.01)
elseif(KIND STREQUAL "add_subdirectory")
  run(${CMAKE_COMMAND} ${common} -S "${consumer_source}" -B "${WORK_DIR}/consumer" -DGLINT_SOURCE_DIR=${GLINT_SOURCE_DIR})
else()
  message(FATAL_ERROR "unknown KIND '${KIND}'")
endif()
run(${CMAKE_COMMAND} --build "${WORK_DIR}/consumer")
run("${WORK_DIR}/consumer/consumer")
