add_test(NAME io.command_line
         COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/io/cli_test.py
                 $<TARGET_FILE:fpmshell> ${CMAKE_BINARY_DIR}/io_test_work)
set_tests_properties(io.command_line PROPERTIES LABELS io TIMEOUT 300)
