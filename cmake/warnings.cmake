# Warnings for our own targets only (third-party headers are included as SYSTEM).
function(fpmshell_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow)
endfunction()
