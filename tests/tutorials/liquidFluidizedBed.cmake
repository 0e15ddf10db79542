# liquidFluidizedBed tests (FOAMDEM_WORK and TUT come from integration.cmake)

# CI variant: the bed of 2 500 1 mm glass spheres in water at two
# velocities (Richardson-Zaki voidage 0.8 and 0.6), the law with the best
# documented agreement, |eps - eps_RZ| within the bound stated in Allrun
# (Richardson & Zaki with Brown & Lawler's U_t and Garside & Al-Dibouni's
# n: an independent reference). About 2-3 min on one free core.
add_test(NAME liquidFluidizedBed.ci
    COMMAND ${TUT} liquidFluidizedBed ${FOAMDEM_WORK}/liquidFluidizedBed -ci)
set_tests_properties(liquidFluidizedBed.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900)
