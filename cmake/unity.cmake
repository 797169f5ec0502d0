# Unity builds of the libraries and the conformesh command (CMake's UNITY_BUILD): each target's sources are compiled
# in a few combined translation units, so Eigen, CLI11 and nlohmann-json are parsed and their templates instantiated
# once per batch instead of once per file. From scratch this halves the CPU time of `bootstrap.sh run` (measured:
# docs/benchmarks.md, "Build time"); rebuilding after one edit recompiles a whole batch, so developers' builds keep it
# off. Every source is written to compile both ways: file-local helpers have names unique within their library.
option(CONFORMESH_UNITY_BUILD "Compile the libraries and the conformesh command as a few combined sources each" OFF)

# conformesh_unity_build(TARGET BATCHES): with CONFORMESH_UNITY_BUILD, compile TARGET's sources (those listed when it
# is called) in BATCHES combined units of equal size. Chosen by measurement on two cores (docs/benchmarks.md):
# intrinsic's sources in three batches (its Eigen-heavy flow and measure files share most instantiations: four cost
# 20 s more), the others in two, so that the last batches to start — the command's — finish together.
function(conformesh_unity_build target batches)
  if(CONFORMESH_UNITY_BUILD)
    get_target_property(sources ${target} SOURCES)
    list(LENGTH sources count)
    math(EXPR size "(${count} + ${batches} - 1) / ${batches}")
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${size})
  endif()
endfunction()
