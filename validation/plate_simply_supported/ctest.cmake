# Quick variant (make test) and full variant (make validate) of this problem; see ../README.md.
fpmshell_validation_problem()
