# Quick variant (label verification, part of make test) and full variant (label validation,
# make validate) of this problem; see ../README.md.
add_test(NAME verification.${FPMSHELL_PROBLEM}
         COMMAND ${FPMSHELL_PYTHON} ${FPMSHELL_PROBLEM_DIR}/run.py --fpmshell $<TARGET_FILE:fpmshell>
                 --out ${CMAKE_BINARY_DIR}/validation/${FPMSHELL_PROBLEM}-quick --quick)
set_tests_properties(verification.${FPMSHELL_PROBLEM} PROPERTIES LABELS verification TIMEOUT 600)
add_test(NAME validation.${FPMSHELL_PROBLEM}
         COMMAND ${FPMSHELL_PYTHON} ${FPMSHELL_PROBLEM_DIR}/run.py --fpmshell $<TARGET_FILE:fpmshell>
                 --out ${CMAKE_BINARY_DIR}/validation/${FPMSHELL_PROBLEM})
# The paper's 30 x 128 mesh alone takes about 5 hours on 2 cores (739 235 steps), the coarse
# meshes about 1 hour after it (run.py keeps to one thread per core).
set_tests_properties(validation.${FPMSHELL_PROBLEM} PROPERTIES LABELS validation TIMEOUT 28800)
