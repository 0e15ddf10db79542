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
    LABELS "integration;tutorial" TIMEOUT 900)
