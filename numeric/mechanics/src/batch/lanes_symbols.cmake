# Requires every function an instruction set's lane object defines (nm: T, W) to be of that instruction
# set: its entry points, or code instantiated on its xsimd batch type. Anything else (an inline function
# of Eigen, the standard library or impact3d at double) could be picked by the linker for the whole
# program, and would carry instructions the CPU may not have. The baseline's object (compiled with no
# flag of its own: sse2) may share such inline (weak) functions, since its instructions are every
# x86-64's; they are counted. (clang at -O1 leaves one of the standard library's there, which GCC inlines.)
# The object's static initializer (the <iostream> object Eigen's headers bring, GCC 12), and under the
# sanitizers their constructors and destructors, run on every CPU: they must hold no VEX or EVEX
# instruction.
# Variables: NM, OBJDUMP, OBJECT, ARCH_NAME (entry suffix), ARCH_TYPE (the xsimd arch, as nm -C prints it),
# ARCH_FLAGS (the object's own compiler flags, empty for the baseline).
execute_process(COMMAND ${NM} -C --defined-only ${OBJECT} OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "${NM} failed on ${OBJECT}")
endif()
string(REPLACE "\n" ";" lines "${symbols}")
set(functions 0)
set(entries 0)
set(shared 0)
if(NOT DEFINED ARCH_FLAGS)
  message(FATAL_ERROR "ARCH_FLAGS is not given: without it every object would pass as the baseline")
endif()
string(STRIP "${ARCH_FLAGS}" ARCH_FLAGS)
foreach(line IN LISTS lines)
  if(line MATCHES "^[0-9a-f]+ ([TW]) (.*)$")
    set(kind "${CMAKE_MATCH_1}")
    set(name "${CMAKE_MATCH_2}")
    math(EXPR functions "${functions} + 1")
    string(FIND "${name}" "xsimd::batch<double, ${ARCH_TYPE}" of_arch)
    if(name MATCHES "^impact3d::batch::lanes::(pc_crash|wach|brach|sin_cos)_${ARCH_NAME}\\(")
      math(EXPR entries "${entries} + 1")
    elseif(of_arch EQUAL -1 AND ARCH_FLAGS STREQUAL "" AND kind STREQUAL "W")
      math(EXPR shared "${shared} + 1")
    elseif(of_arch EQUAL -1)
      message(FATAL_ERROR "${OBJECT} defines ${name}, which is not of ${ARCH_TYPE}")
    endif()
  endif()
endforeach()
if(NOT entries EQUAL 4)
  message(FATAL_ERROR "${OBJECT} defines ${entries} of the 4 lane entry points (pc_crash, wach, brach, sin_cos)")
endif()
# The static initializers, found by their symbols (wherever the compiler put them), each disassembled.
execute_process(COMMAND ${NM} --defined-only ${OBJECT} OUTPUT_VARIABLE raw_symbols RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "${NM} failed on ${OBJECT}")
endif()
# GCC's _GLOBAL__sub_I_* may call __static_initialization_and_destruction_* when it is not inlined, and
# Clang's initializers are __cxx_global_var_init*, the sanitizers' asan.module_ctor and the like: every one
# of them is disassembled.
string(REGEX MATCHALL "(_GLOBAL__sub_I_|__static_initialization_and_destruction_|__cxx_global_var_init|asan\\.module_[cd]tor|sancov\\.module_ctor)[A-Za-z0-9_.$]*"
       initializers "${raw_symbols}")
list(REMOVE_DUPLICATES initializers)
# GNU objdump names one function by --disassemble=, LLVM's (clang's CMAKE_OBJDUMP) by --disassemble-symbols=.
execute_process(COMMAND ${OBJDUMP} --version OUTPUT_VARIABLE objdump_version ERROR_QUIET)
set(one_function --disassemble=)
if(objdump_version MATCHES "LLVM")
  set(one_function --disassemble-symbols=)
endif()
set(instructions 0)
foreach(init IN LISTS initializers)
  execute_process(COMMAND ${OBJDUMP} -d --no-show-raw-insn ${one_function}${init} ${OBJECT} OUTPUT_VARIABLE startup
                  RESULT_VARIABLE rc ERROR_QUIET)
  string(REPLACE "\n" ";" startup_lines "${startup}")
  set(own 0)
  foreach(line IN LISTS startup_lines)
    if(line MATCHES "^ +[0-9a-f]+:[ \t]+([a-z0-9]+)")
      math(EXPR own "${own} + 1")
      if(CMAKE_MATCH_1 MATCHES "^v" OR line MATCHES "%[yz]mm|%k[0-7]")
        message(FATAL_ERROR "${OBJECT}'s static initializer ${init} uses a wide instruction: ${line}")
      endif()
    endif()
  endforeach()
  if(rc OR own EQUAL 0)
    message(FATAL_ERROR "${OBJDUMP} shows no instruction of ${init} in ${OBJECT}")
  endif()
  math(EXPR instructions "${instructions} + ${own}")
endforeach()
list(LENGTH initializers count)
message(STATUS "${functions} functions, the 4 entry points and the rest of ${ARCH_TYPE} and ${shared} shared (the baseline's only); "
               "${count} functions run at start-up or exit, of ${instructions} instructions, none wide")
