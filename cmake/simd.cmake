# fpmshell_select_simd(OUT): the -march value of the build (empty: the compiler's default),
# from FPMSHELL_SIMD. "auto" asks the CPU of the build machine which x86-64 level it runs.
include(CheckCXXSourceRuns)
function(fpmshell_select_simd out)
  set(level "")
  if(FPMSHELL_SIMD STREQUAL "auto")
    if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
      check_cxx_source_runs("
        int main() {
          __builtin_cpu_init();
          return __builtin_cpu_supports(\"avx512f\") && __builtin_cpu_supports(\"avx512dq\") &&
                 __builtin_cpu_supports(\"avx512bw\") && __builtin_cpu_supports(\"avx512vl\") &&
                 __builtin_cpu_supports(\"avx512cd\") ? 0 : 1;
        }" FPMSHELL_CPU_X86_64_V4)
      check_cxx_source_runs("
        int main() {
          __builtin_cpu_init();
          return __builtin_cpu_supports(\"avx2\") && __builtin_cpu_supports(\"fma\") &&
                 __builtin_cpu_supports(\"bmi2\") ? 0 : 1;
        }" FPMSHELL_CPU_X86_64_V3)
      if(FPMSHELL_CPU_X86_64_V4)
        set(level x86-64-v4)
      elseif(FPMSHELL_CPU_X86_64_V3)
        set(level x86-64-v3)
      endif()
    endif()
  elseif(NOT FPMSHELL_SIMD STREQUAL "off")
    set(level ${FPMSHELL_SIMD})
  endif()
  # libstdc++'s <experimental/simd> is written for g++: compiled by clang (14) for AVX-512, its
  # masked assignment (where(m, x) = y) and shifts give wrong lanes even at -O0
  # (test SimdMath.EveryLaneEqualsItsScalar). Its AVX2 code is right under clang.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang" AND level STREQUAL "x86-64-v4")
    if(NOT FPMSHELL_SIMD STREQUAL "auto")
      message(FATAL_ERROR "FPMSHELL_SIMD=x86-64-v4 needs g++: libstdc++'s SIMD library computes "
                          "wrong AVX-512 lanes when clang compiles it; use x86-64-v3 with clang")
    endif()
    set(level x86-64-v3)
    message(STATUS "fpmshell: clang: AVX2 (x86-64-v3), as libstdc++'s SIMD is wrong on AVX-512 "
                   "under clang")
  endif()
  if(level)
    message(STATUS "fpmshell: instruction set -march=${level}")
  else()
    message(STATUS "fpmshell: instruction set of the compiler's default")
  endif()
  set(${out} ${level} PARENT_SCOPE)
endfunction()
