# ErgunPackedBed tests (FOAMDEM_WORK and TUT come from integration.cmake)

# Pressure drop inside a frozen bed of 3000 spheres within 2 % of Ergun with
# the bed's measured void fraction, at three velocities below U_mf
add_test(NAME ErgunPackedBed.ci
    COMMAND ${TUT} ErgunPackedBed ${FOAMDEM_WORK}/ErgunPackedBed -ci)
set_tests_properties(ErgunPackedBed.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300)

# The same with Euler's default flux ddt correction and a small time step:
# guards the eps_f factor of pisoDEMFoam's ddtCorr term (without it the
# steady pressure drop depended on deltaT and was ~40 % low at this step)
add_test(NAME ErgunPackedBed.ddtCorr
    COMMAND ${TUT} ErgunPackedBed ${FOAMDEM_WORK}/ErgunPackedBed_ddtCorr
            -ci -ddt Euler -dt 2.5e-4)
set_tests_properties(ErgunPackedBed.ddtCorr PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300)
