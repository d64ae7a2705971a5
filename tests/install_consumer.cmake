# Install the build tree into a scratch prefix, build tests/consumer against it with find_package, run it,
# and compare its output with the installed CLI's P_n for the same case.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed")
endif()
# The consumer is built as the project was (a sanitizer build's libraries need the sanitizer runtime).
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}/build -G ${GENERATOR}
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_CXX_COMPILER=${CXX} "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
                        "-DCMAKE_EXE_LINKER_FLAGS=${LINK_FLAGS}" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer against the installed package failed")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK_DIR}/build RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed")
endif()
execute_process(COMMAND ${WORK_DIR}/build/consumer ${EXAMPLE} OUTPUT_VARIABLE pn RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
execute_process(COMMAND ${WORK_DIR}/prefix/bin/impact3d solve ${EXAMPLE} --format json OUTPUT_VARIABLE json RESULT_VARIABLE rc2)
if(rc OR rc2)
  message(FATAL_ERROR "running the consumer or the installed CLI failed")
endif()
string(JSON cli_pn GET "${json}" results 0 impulse contact 0)
if(NOT pn STREQUAL cli_pn)
  message(FATAL_ERROR "consumer P_n ${pn} differs from the installed CLI's ${cli_pn}")
endif()
message(STATUS "consumer P_n = ${pn}, as the installed CLI")
