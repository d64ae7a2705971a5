# Install the build tree into a scratch prefix and import the installed package from its site-packages
# directory (and from nowhere else): it must solve Figure 8 as the build tree's module does.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed")
endif()
set(site ${WORK_DIR}/prefix/${SITE})
if(NOT EXISTS ${site}/impact3d/__init__.py OR NOT EXISTS ${site}/impact3d/__init__.pyi)
  message(FATAL_ERROR "no package impact3d with its stubs in ${site}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON} -I -c
                        "import sys; sys.path.insert(0, '${site}'); import impact3d; assert impact3d.__file__.startswith('${site}'), impact3d.__file__; r = impact3d.solve(impact3d.read_case('${EXAMPLE}')); print(r['results'][0]['impulse']['contact'][0])"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(rc)
  message(FATAL_ERROR "the installed package does not import and solve: ${err}")
endif()
message(STATUS "installed impact3d solves Figure 8: P_n = ${out}")
