# The paper's 30 x 128 mesh alone takes about 5 hours on 2 cores (739 235 steps), the coarse
# meshes about 1 hour after it (run.py keeps to one thread per core).
fpmshell_validation_problem(FULL_TIMEOUT 28800)
