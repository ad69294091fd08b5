# Quick variant (label verification, part of make test) and full variant (label validation,
# make validate) of this problem; see ../README.md.
add_test(NAME verification.${FPMSHELL_PROBLEM}
         COMMAND ${FPMSHELL_PYTHON} ${FPMSHELL_PROBLEM_DIR}/run.py --fpmshell $<TARGET_FILE:fpmshell>
                 --out ${CMAKE_BINARY_DIR}/validation/${FPMSHELL_PROBLEM}-quick --quick)
set_tests_properties(verification.${FPMSHELL_PROBLEM} PROPERTIES LABELS verification TIMEOUT 600)
add_test(NAME validation.${FPMSHELL_PROBLEM}
         COMMAND ${FPMSHELL_PYTHON} ${FPMSHELL_PROBLEM_DIR}/run.py --fpmshell $<TARGET_FILE:fpmshell>
                 --out ${CMAKE_BINARY_DIR}/validation/${FPMSHELL_PROBLEM})
set_tests_properties(validation.${FPMSHELL_PROBLEM} PROPERTIES LABELS validation TIMEOUT 3600)
