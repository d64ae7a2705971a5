# Runs impact3d-derive on the sources in SOURCES. The inputs hash (manifest.json) is computed by the
# generator over the code of SOURCES, comments and blank space removed: `impact3d-derive --hash-sources`.
# Variables: DERIVE, SOURCES, GENERATED (the generated/ folder), PAPERS.
execute_process(COMMAND ${DERIVE} --generated ${GENERATED} --papers ${PAPERS} --sources ${SOURCES} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "impact3d-derive failed")
endif()
