# Warnings for our own targets only (third-party headers are included as SYSTEM).
function(fpmshell_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
  # Without OpenMP (-DFPMSHELL_OPENMP=OFF) the loops' pragmas are meant to be ignored.
  if(NOT FPMSHELL_OPENMP)
    target_compile_options(${target} PRIVATE -Wno-unknown-pragmas)
  endif()
endfunction()
