# mixedBedNonSpherical (FOAMDEM_WORK and TUT come from integration.cmake)

# 200 multisphere bodies (rods and plates), Hoelzer-Sommerfeld + Di Felice:
# void fraction within [alphaMin, 1], no NaN, body/sphere count and mass
# constant (validate.py)
add_test(NAME mixedBedNonSpherical.ci
    COMMAND ${TUT} mixedBedNonSpherical ${FOAMDEM_WORK}/mixedBedNonSpherical -ci)
set_tests_properties(mixedBedNonSpherical.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300)
