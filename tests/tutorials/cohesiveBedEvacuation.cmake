# cohesiveBedEvacuation tests (FOAMDEM_WORK and TUT come from integration.cmake)

# CI variant (snappyHexMesh mesh of 7 000-9 000 cells turned 25 degrees,
# k-epsilon, driven by pressure, 3 000 cohesive particles released below the
# tube's mouth, 0.05 s): the flow is established (vent flow = supply flow
# within 1 %, vent velocity > 30 m/s, steady within 5 % over the last
# quarter), particles crossed the vent and were deleted, present + deleted
# = initial at every line of the DEM's time series, and the run ended
# (postprocess.py --ci)
add_test(NAME cohesiveBedEvacuation.ci
    COMMAND ${TUT} cohesiveBedEvacuation ${FOAMDEM_WORK}/cohesiveBedEvacuation -ci)
set_tests_properties(cohesiveBedEvacuation.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_SETUP cohesiveBedEvacuation_ci)

# Restart (issue 15 part 2): the CI run continued from its 0.03 s write
# (fields and the library's DEM restart) to 0.05 s with ./Allrun -ci
# -continue: postprocess.py --ci passes on the joined series (the vent's
# deletion count carried through the restart) and the particle counts
# follow the straight run's within 3 particles (2 measured)
add_test(NAME continuation.cohesiveBedEvacuation
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialContinuation
            ${FOAMDEM_WORK}/cohesiveBedEvacuation
            ${FOAMDEM_WORK}/cohesiveBedEvacuation_continue 0.03
            --rows DEM/post/evacuation.dat:3:1,2,3,4,5 -- -ci)
set_tests_properties(continuation.cohesiveBedEvacuation PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_REQUIRED cohesiveBedEvacuation_ci)

# The same at np 2 (issue 15: the continuation of every tutorial, in
# parallel too; particles deleted at the vent from either rank): the CI run
# at np 2 (postprocess.py --ci must pass), then its copy continued from
# 0.03 s with ./Allrun -ci -np 2 -continue, with the bound above
add_test(NAME cohesiveBedEvacuation.np2
    COMMAND ${TUT} cohesiveBedEvacuation ${FOAMDEM_WORK}/cohesiveBedEvacuation_np2 -ci -np 2)
set_tests_properties(cohesiveBedEvacuation.np2 PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_SETUP cohesiveBedEvacuation_np2)
add_test(NAME continuation.cohesiveBedEvacuation.np2
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialContinuation
            ${FOAMDEM_WORK}/cohesiveBedEvacuation_np2
            ${FOAMDEM_WORK}/cohesiveBedEvacuation_continue_np2 0.03
            --rows DEM/post/evacuation.dat:3:1,2,3,4,5 -- -ci -np 2)
set_tests_properties(continuation.cohesiveBedEvacuation.np2 PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_REQUIRED cohesiveBedEvacuation_np2)

# Cohesion through the coupled solver (issue 14 part 5): the fluidizedBed CI
# bed (4 000 spheres of 2 mm, E = 1 MPa, sweep to 2 U_mf) with simplified
# JKR cohesion of 1e5 J/m^3 (this case's value; particle-particle and
# particle-wall) in the coupled stage holds (mean height change -0.19 mm,
# kinetic energy per particle 8e-12 J) where the same packed bed without
# cohesion (the fluidizedBed.ci run) expands by 13 mm (3e-7 J); seen
# failing with the cohesion energy density 0 in the coupled stage
add_test(NAME cohesion.bedHolds
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkCohesiveBed
            ${FOAMDEM_WORK}/cohesion_bedHolds ${FOAMDEM_WORK}/fluidizedBed 1e5)
set_tests_properties(cohesion.bedHolds PROPERTIES
    LABELS "integration" TIMEOUT 900
    FIXTURES_REQUIRED fluidizedBed_ci)
