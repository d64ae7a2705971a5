# `target`'s sources compiled as one translation unit (CMake's unity build): they parse the same
# headers of impact3d and instantiate the same templates, which once compiled per source were much of
# the build. The per-scalar wrappers stay apart (numeric/CMakeLists.txt), so the wide types compile in
# parallel; a source with options of its own CMake leaves apart too. Not the case format: its reader
# and writers are batch's path for every row, and one unit there measured slower (BENCHMARKS.md).
function(impact3d_one_unit target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 0)
endfunction()
