# mixedBedNonSpherical (FOAMDEM_WORK and TUT come from integration.cmake)

# 200 multisphere bodies (rods and plates), Hoelzer-Sommerfeld + Di Felice,
# fluidised at 0.08 m/s through an empty inlet cell layer: void fraction
# within [alphaMin, 1] and 1 in the inlet layer, no NaN, body/sphere count
# and mass constant, bed expanded >= 1.2 x its packed height, pressure drop
# within [0.7, 1.25] x the buoyant weight per area (validate.py)
add_test(NAME mixedBedNonSpherical.ci
    COMMAND ${TUT} mixedBedNonSpherical ${FOAMDEM_WORK}/mixedBedNonSpherical -ci)
set_tests_properties(mixedBedNonSpherical.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300)

# Multisphere bodies in parallel: np 1 and np 2 (bed cut in two slabs along
# x) both pass the checks above, with the same body and sphere counts, and
# agree on the fluidised bed's mean height (8 %) and dP/(W/A) (0.10), about
# twice the spread between packing seeds (tests/parallel/compareMixedBed)
add_test(NAME parallel.mixedBedNonSpherical.statistics
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/parallel/compareMixedBed
            ${FOAMDEM_WORK}/parallel_mixedBed)
set_tests_properties(parallel.mixedBedNonSpherical.statistics PROPERTIES
    LABELS "integration;parallel" TIMEOUT 600 PROCESSORS 2)
