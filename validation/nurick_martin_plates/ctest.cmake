# Quick variant (make test): two impulses on the 16-ring disc, about 10 s; full (make validate):
# five impulses on 16 and 24 rings and two other plates, about 2 min on 1 thread.
fpmshell_validation_problem(QUICK_TIMEOUT 300 FULL_TIMEOUT 1800)
