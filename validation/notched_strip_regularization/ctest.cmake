# Quick variant (make test) and full variant (make validate) of this problem; see ../README.md.
# The full variant runs 0.625 mm elements through the neck (about 10 minutes on 16 cores).
fpmshell_validation_problem(QUICK_TIMEOUT 900 FULL_TIMEOUT 7200)
