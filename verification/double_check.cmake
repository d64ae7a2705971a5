# Solves every reference case with the CLI at double precision and compares with the reference suite.
# Tolerances: double's forward error is about 16 eps kappa(K) relative to each quantity's scale; the
# suite's largest kappa is 633 and its largest magnitude about 3e4 (impulses in N s), so rtol = 1e-11
# (16 eps 633 = 2.3e-12) and atol = 1e-7 (2.3e-12 * 3e4 = 6.7e-8) bound it with a little room.
# Variables: CLI, REFERENCE, WORK, CASES.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
foreach(c IN LISTS CASES)
  get_filename_component(name ${c} NAME)
  execute_process(COMMAND ${CLI} solve ${c} --format json OUTPUT_FILE ${WORK}/${name} RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "impact3d solve ${c} failed")
  endif()
endforeach()
execute_process(COMMAND ${CLI} compare ${REFERENCE} ${WORK} --rtol 1e-11 --atol 1e-7 RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "double results differ from the reference beyond the rounding bound")
endif()
