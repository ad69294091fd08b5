# Quick variant (label verification, part of make test: half 8x32 and 16x64, about 3 s) and full
# variant (label validation, make validate: five meshes up to 48x192, about 4 min on 1 thread);
# see ../README.md.
add_test(NAME verification.${FPMSHELL_PROBLEM}
         COMMAND ${FPMSHELL_PYTHON} ${FPMSHELL_PROBLEM_DIR}/run.py --fpmshell $<TARGET_FILE:fpmshell>
                 --out ${CMAKE_BINARY_DIR}/validation/${FPMSHELL_PROBLEM}-quick --quick)
set_tests_properties(verification.${FPMSHELL_PROBLEM} PROPERTIES LABELS verification TIMEOUT 120)
add_test(NAME validation.${FPMSHELL_PROBLEM}
         COMMAND ${FPMSHELL_PYTHON} ${FPMSHELL_PROBLEM_DIR}/run.py --fpmshell $<TARGET_FILE:fpmshell>
                 --out ${CMAKE_BINARY_DIR}/validation/${FPMSHELL_PROBLEM})
set_tests_properties(validation.${FPMSHELL_PROBLEM} PROPERTIES LABELS validation TIMEOUT 1800)
