# consumer_agrees(CONSUMER CLI EXAMPLE WHAT): the consumer program and the impact3d program print the
# same P_n for EXAMPLE (the consumer's from the library, the program's from its JSON); WHAT names the
# consumer in messages.
function(consumer_agrees consumer cli example what)
  execute_process(COMMAND ${consumer} ${example} OUTPUT_VARIABLE pn RESULT_VARIABLE rc OUTPUT_STRIP_TRAILING_WHITESPACE)
  execute_process(COMMAND ${cli} solve ${example} --format json OUTPUT_VARIABLE json RESULT_VARIABLE rc2)
  if(rc OR rc2)
    message(FATAL_ERROR "running the ${what} or the program failed")
  endif()
  string(JSON cli_pn GET "${json}" results 0 impulse contact 0)
  if(NOT pn STREQUAL cli_pn)
    message(FATAL_ERROR "${what} P_n ${pn} differs from the program's ${cli_pn}")
  endif()
  message(STATUS "${what} P_n = ${pn}, as the program")
endfunction()
