# Quick variant: half 8x32 and 16x64, about 3 s; full: five meshes up to 48x192, about 4 min
# on 1 thread (../README.md).
fpmshell_validation_problem(QUICK_TIMEOUT 120 FULL_TIMEOUT 1800)
