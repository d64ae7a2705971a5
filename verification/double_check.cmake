# Solves every reference case with the CLI at double precision and compares with the reference suite,
# each case within its own rounding bound: `compare --rtol-from-bound` takes the case's rtol from the
# double results' `rounding_bound` (kResultRoundings eps kappa(K) cond(J) (|v_IC1|+|v_IC2|)/V_rn
# (1+|V_cp/V_n|), rounding.hpp), and atol = rtol times the case's largest magnitude. A harder case
# brings its own tolerance; no constant here is tuned to the suite.
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
execute_process(COMMAND ${CLI} compare ${REFERENCE} ${WORK} --rtol-from-bound RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "double results differ from the reference beyond their own rounding bound")
endif()
