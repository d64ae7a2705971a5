# The inputs hash follows the code of symbolic/src and nothing else: on a scratch copy of the sources,
# added comments, blank lines and blanks leave it unchanged; a changed string literal holding `//` and a
# changed constant change it. The real tree is only read.
# Variables: DERIVE, SOURCES, WORK.
function(hash_of dir out)
  execute_process(COMMAND ${DERIVE} --hash-sources ${dir} OUTPUT_VARIABLE h RESULT_VARIABLE rc
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(rc OR NOT h MATCHES "^[0-9a-f]+$")
    message(FATAL_ERROR "impact3d-derive --hash-sources ${dir} failed: ${h}")
  endif()
  set(${out} ${h} PARENT_SCOPE)
endfunction()

# A fresh copy of the sources in WORK/NAME with OLD replaced by NEW in FILE (OLD must occur).
function(edited_copy name file old new)
  file(REMOVE_RECURSE ${WORK}/${name})
  file(COPY ${SOURCES}/ DESTINATION ${WORK}/${name})
  file(READ ${WORK}/${name}/${file} text)
  string(FIND "${text}" "${old}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "hash check: `${old}` not found in ${file}; update symbolic/hash_check.cmake")
  endif()
  string(REPLACE "${old}" "${new}" text "${text}")
  file(WRITE ${WORK}/${name}/${file} "${text}")
endfunction()

hash_of(${SOURCES} original)
file(REMOVE_RECURSE ${WORK})

# Comments of both kinds (one holding quotes), blank lines, trailing and repeated blanks.
edited_copy(comments main.cpp "int main(int argc, char** argv) {"
            "/* A block comment,\n   it's \"quoted\" and spans lines. */\n\nint main(int argc, /* inline */ char**   argv) {  // trailing   \n\n  \n")
file(APPEND ${WORK}/comments/codegen.hpp "\n// A comment added at the end.  \n\n")
hash_of(${WORK}/comments with_comments)
if(NOT with_comments STREQUAL original)
  message(FATAL_ERROR "added comments changed the inputs hash: ${original} -> ${with_comments}")
endif()

# Code: a string literal that holds `//`, and a constant.
edited_copy(literal codegen.cpp "\"/// Operations: \"" "\"/// Operation count: \"")
hash_of(${WORK}/literal with_literal)
edited_copy(constant codegen.cpp "ops += 2;" "ops += 3;")
hash_of(${WORK}/constant with_constant)
if(with_literal STREQUAL original OR with_constant STREQUAL original)
  message(FATAL_ERROR "a code change left the inputs hash unchanged (${original})")
endif()
file(REMOVE_RECURSE ${WORK})
message(STATUS "inputs hash ${original}: unchanged by comments, changed by code")
