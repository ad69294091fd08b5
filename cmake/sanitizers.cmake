# Instrumented builds (README "Reliability"), each in a build folder of its own:
#   FPMSHELL_SANITIZE=ON  AddressSanitizer + UndefinedBehaviorSanitizer on everything (make
#                         sanitize runs the unit and io tests and the examples in such a build)
#   FPMSHELL_FUZZ=ON      the same with libFuzzer's coverage instrumentation, and the fuzz targets
#                         linked with libFuzzer (make fuzz); needs clang
#   FPMSHELL_TSAN=ON      ThreadSanitizer (make tsan); needs clang, whose OpenMP runtime (libomp)
#                         tells ThreadSanitizer about its barriers and tasks through libarcher;
#                         g++'s libgomp does not, and every parallel loop would be a false report
# A sanitizer's report ends the process with an error: -fno-sanitize-recover makes undefined
# behaviour as fatal as a bad memory access, so that no test passes over it.
option(FPMSHELL_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(FPMSHELL_FUZZ "Build the fuzz targets with libFuzzer (clang), sanitizers on" OFF)
option(FPMSHELL_TSAN "Build with ThreadSanitizer (clang)" OFF)

# -ffp-contract=off: with the sanitizers' instrumentation g++ contracts a * b + c into an FMA in
# some inlined copies of a kernel and not in others, and a SIMD lane would differ from its scalar
# in the last bit (tests SimdMath and PipelinedDivision.EveryLaneEqualsItsScalar); without
# contraction both round alike, as in the Release build.
set(_fpmshell_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=undefined
    -fno-omit-frame-pointer -ffp-contract=off)
if(FPMSHELL_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "FPMSHELL_FUZZ needs clang (libFuzzer): configure with "
                        "-DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(${_fpmshell_sanitizers} -fsanitize=fuzzer-no-link)
  # Generated meshes of at most 10^5 elements (io/mesh_input.hpp; 2e7 otherwise): reading a
  # 383 000-element plate took 3 s under the sanitizers, so a few million would pass for a hang.
  add_compile_definitions(FPMSHELL_MAX_MESH_ELEMENTS=1.0e5)
  add_link_options(-fsanitize=address,undefined)
elseif(FPMSHELL_TSAN)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "FPMSHELL_TSAN needs clang (libomp and libarcher): configure with "
                        "-DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_link_options(-fsanitize=thread)
elseif(FPMSHELL_SANITIZE)
  add_compile_options(${_fpmshell_sanitizers})
  add_link_options(-fsanitize=address,undefined)
endif()

# Instrumented code runs several times slower (ASan ~3x, TSan 5-15x): the time limits of the io
# and fuzz-replay tests (ctest TIMEOUT) are multiplied by FPMSHELL_TIMEOUT_SCALE in such builds.
if(FPMSHELL_SANITIZE OR FPMSHELL_FUZZ OR FPMSHELL_TSAN)
  set(FPMSHELL_TIMEOUT_SCALE 10)
else()
  set(FPMSHELL_TIMEOUT_SCALE 1)
endif()
