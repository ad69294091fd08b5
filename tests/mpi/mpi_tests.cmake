# Distributed runs (label "mpi", part of make test): mpirun -np 2 against one process, byte for
# byte. Only where MPI and its launcher were found; RUN_SERIAL: ranks that wait on each other
# while other tests hold the cores slow down many times over.
if(MPI_CXX_FOUND AND MPIEXEC_EXECUTABLE)
  add_test(NAME mpi.distributed_runs
           COMMAND ${FPMSHELL_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/mpi/distributed_test.py
                   $<TARGET_FILE:fpmshell> ${MPIEXEC_EXECUTABLE} ${CMAKE_BINARY_DIR}/mpi_test_work
                   $<TARGET_FILE:fpmshell_with_test_laws>)
  # OpenMPI refuses to start as root unless told (CI containers run as root); a rank waiting
  # for a message yields its core instead of spinning on it.
  set_tests_properties(mpi.distributed_runs PROPERTIES LABELS mpi TIMEOUT 900 RUN_SERIAL TRUE
                       ENVIRONMENT
                       "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_mpi_yield_when_idle=1;OMP_NUM_THREADS=1")
endif()
