# Quick variant (make test: the two coarse meshes, about 10 s) and full variant (make validate)
# of this problem; see ../README.md.
fpmshell_validation_problem()
