# Runs impact3d-derive with the SHA-256 of symbolic/src (file names and contents, sorted by name).
# Variables: DERIVE, SOURCES, GENERATED, PAPERS.
file(GLOB files RELATIVE ${SOURCES} ${SOURCES}/*)
list(SORT files)
set(all "")
foreach(f IN LISTS files)
  file(SHA256 ${SOURCES}/${f} h)
  string(APPEND all "${f} ${h}\n")
endforeach()
string(SHA256 inputs_hash "${all}")
execute_process(COMMAND ${DERIVE} --generated ${GENERATED} --papers ${PAPERS} --inputs-hash ${inputs_hash}
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "impact3d-derive failed")
endif()
