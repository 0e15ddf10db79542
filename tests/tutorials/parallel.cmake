# Parallel tests on the bench fluidBed case (bench/cases/fluidBed, set up by
# bench/bench.py). FOAMDEM_WORK comes from integration.cmake, which includes
# this file with the other tests/tutorials/*.cmake.
set(PARALLEL_DIR ${CMAKE_CURRENT_SOURCE_DIR}/parallel)

# np = 1 and np = 2 agree on the statistics of a fluidised bed (3 600
# particles on the distributor one cell above the inlet, 2 U_mf = 2.126 m/s,
# 0.4 s; ~100 s on 2 cores): particle count exact, time-mean centre-of-mass
# height within 3 %, time-mean pressure drop within 10 % over 0.2-0.4 s
# (about 5 and 2.5 times the scatter between perturbed serial runs, twice
# the batch standard error; doc/performance.md). 467 s measured with
# another MPI job on the machine (ranks wait for each other): timeout 1200 s
add_test(NAME parallel.fluidBed.statistics
    COMMAND ${PARALLEL_DIR}/compareFluidBed ${FOAMDEM_WORK}/parallel_fluidBed)
set_tests_properties(parallel.fluidBed.statistics PROPERTIES
    LABELS "integration;parallel" TIMEOUT 1200 PROCESSORS 2)

# Exchange bytes per rank follow the particles the rank moves: CFD and DEM
# slabs crossed at N and 2N particles (bytes per moved particle constant
# within 2 %; bytes measured as handed to MPI), and only the 16 B of size
# messages per step with aligned slabs at 2N
add_test(NAME parallel.exchange.scalesWithLocal
    COMMAND ${PARALLEL_DIR}/checkExchangeScaling ${FOAMDEM_WORK}/parallel_exchange)
set_tests_properties(parallel.exchange.scalesWithLocal PROPERTIES
    LABELS "integration;parallel" TIMEOUT 300 PROCESSORS 2)

# np 4 (oversubscribed): DEM slabs along x (4 1 1), CFD (2 2 1). Each rank's
# neighbour lists, and the ranks of every message of every coupling step
# (the buffer sizes included), equal those the geometry allows: rank 0 never
# addresses ranks 1 and 3, rank 3 never 0 and 2; no step falls back to all
# ranks. Seen failing with every rank as neighbour and with the fallback
# forced (2026-12-03). ~40 s
add_test(NAME parallel.exchange.neighboursOnly
    COMMAND ${PARALLEL_DIR}/checkExchangeNeighbours ${FOAMDEM_WORK}/parallel_neighbours)
set_tests_properties(parallel.exchange.neighboursOnly PROPERTIES
    LABELS "integration;parallel" TIMEOUT 300 PROCESSORS 2)
