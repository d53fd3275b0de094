# Warnings on for our own targets (not for third-party headers, included as SYSTEM).
function(hlod_set_warnings target)
  # -Wshadow=local is GCC's; clang (the fuzz build) has no such option.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    set(shadow -Wshadow=local)
  endif()
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic ${shadow}
                                           -Wnon-virtual-dtor -Wno-missing-field-initializers)
  # GCC notes that four-double vectors are returned differently with and without AVX
  # (-Wpsabi); the clustering's vector helpers (pipeline/cluster/WideBounds.h) are always
  # inlined, into baseline or AVX2 code picked at run time, so no call crosses that ABI.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-psabi)
  endif()
endfunction()
