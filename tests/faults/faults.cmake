# Fault tests (label "io"): a full disk, an output folder that cannot be written, a kill during
# a write, damaged restart files, absurd sizes in mesh files, NaN and Inf in numbers.
math(EXPR _timeout_600s "600 * ${FPMSHELL_TIMEOUT_SCALE}")
add_library(fpmshell_full_disk SHARED ${CMAKE_CURRENT_LIST_DIR}/full_disk_preload.cpp)
target_link_libraries(fpmshell_full_disk PRIVATE ${CMAKE_DL_LIBS})
fpmshell_warnings(fpmshell_full_disk)
add_test(NAME io.faults
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_LIST_DIR}/fault_test.py
                 $<TARGET_FILE:fpmshell> $<TARGET_FILE:fpmshell_full_disk>
                 ${CMAKE_BINARY_DIR}/fault_test_work)
set_tests_properties(io.faults PROPERTIES LABELS io TIMEOUT ${_timeout_600s} ENVIRONMENT OMP_NUM_THREADS=1)
