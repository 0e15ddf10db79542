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
