# fluidizedBed tests (FOAMDEM_WORK and TUT come from integration.cmake)

# fluidizedBed, CI variant (4000 particles, short sweep): fluidised-bed
# pressure drop within 2 % of the buoyant bed weight per area, U_mf from the
# decreasing sweep within 10 % of Ergun at the measured voidage, no particle
# lost, void fraction never clipped. About 2-3 min on one free core.
add_test(NAME fluidizedBed.ci
    COMMAND ${TUT} fluidizedBed ${FOAMDEM_WORK}/fluidizedBed -ci)
set_tests_properties(fluidizedBed.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_SETUP fluidizedBed_ci)
