# A double-only build of the library (IMPACT3D_MULTIPRECISION=OFF: no program, tests or symbolic part),
# installed into a scratch prefix; its exported targets must name no MPFR, GMP or quadmath, and
# tests/install/consumer must build against it and print the same P_n as the full build's program.
# Variables: SOURCE_DIR (the project), CONSUMER_DIR, WORK_DIR, EXAMPLE, CLI, GENERATOR, CXX.
file(REMOVE_RECURSE ${WORK_DIR})
# At -O1: what is checked is the package (its targets, its headers, its link), not the code's speed, and
# at -O3 this build was half of the suite's test time (216 of 434 s); the same doubles come out at
# either level (no fused multiply-add outside the SIMD lanes), which the comparison below holds.
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX}
                        -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" -DIMPACT3D_MULTIPRECISION=OFF -DIMPACT3D_BUILD_CLI=OFF
                        -DIMPACT3D_BUILD_TESTS=OFF -DIMPACT3D_BUILD_SYMBOLIC=OFF RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "configuring the double-only library failed")
endif()
# On every core: the rest of the suite is done long before this build is (ctest starts it first).
cmake_host_system_information(RESULT jobs QUERY NUMBER_OF_LOGICAL_CORES)
foreach(step "--build;${WORK_DIR}/build;--parallel;${jobs}" "--install;${WORK_DIR}/build;--prefix;${WORK_DIR}/prefix")
  execute_process(COMMAND ${CMAKE_COMMAND} ${step} RESULT_VARIABLE rc OUTPUT_QUIET)
  if(rc)
    message(FATAL_ERROR "cmake ${step} failed for the double-only library")
  endif()
endforeach()
file(GLOB exported ${WORK_DIR}/prefix/lib*/cmake/impact3d/impact3dTargets*.cmake)
foreach(f IN LISTS exported)
  file(READ ${f} text)
  if(text MATCHES "MPFR|mpfr|gmp|quadmath")
    message(FATAL_ERROR "${f} names a multiprecision library")
  endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${WORK_DIR}/consumer -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX}
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc)
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer RESULT_VARIABLE rc OUTPUT_QUIET)
endif()
if(rc)
  message(FATAL_ERROR "the consumer did not build against the double-only library")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/consumer_agrees.cmake)
consumer_agrees(${WORK_DIR}/consumer/consumer ${CLI} ${EXAMPLE} "double-only consumer")
