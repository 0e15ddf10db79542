# liquidFluidizedBed tests (FOAMDEM_WORK and TUT come from integration.cmake)

# CI variant: the bed of 2 500 1 mm glass spheres in water at two
# velocities (Richardson-Zaki voidage 0.8 and 0.6), the law with the best
# documented agreement, |eps - eps_RZ| within the bound stated in Allrun
# (Richardson & Zaki with Brown & Lawler's U_t and Garside & Al-Dibouni's
# n: an independent reference). About 2-3 min on one free core.
add_test(NAME liquidFluidizedBed.ci
    COMMAND ${TUT} liquidFluidizedBed ${FOAMDEM_WORK}/liquidFluidizedBed -ci)
set_tests_properties(liquidFluidizedBed.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_SETUP liquidFluidizedBed_ci)

# Continuation (issue 15 part 2): a copy of the CI run (liquidFluidizedBed.ci)
# without its writes after 3.4 s (near the end of the first stage's hold),
# continued by ./Allrun -ci -continue (the fields and
# DEM/restart/3.4.restart; validate.py over the joined bed.dat,
# heights.dump and postProcessing/inlet/0 and /3.4, which must pass). The
# bed's history 10 ms after the restart agrees with the straight run's to
# 5e-3 (measured: mean height 5.0e-6, maximum 4.5e-7, kinetic energy
# 4.9e-4; the fields are read back from 8 ASCII digits); then the runs
# part, and results/summary.dat is compared statistically: every number
# within 0.025 absolute (measured: the second stage's voidage 0.6103
# against 0.5937, +0.0166, about 2-3 x the bed's std over the averaging
# window, 0.005-0.008; np 2 against np 1 differ by 0.008; the first
# stage's 0.788694 against 0.788701). Seen failing with DEM/in.liggghts
# reading DEM/post/packed.restart instead of ${foamDEMRestart} (the packed
# bed under the expanded bed's flow: lost atoms at 3.432 s). About 30 s on
# the CI run.
set(CONTINUATION_TUT ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialContinuation)
add_test(NAME continuation.liquidFluidizedBed
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/liquidFluidizedBed
            ${FOAMDEM_WORK}/continuation_liquidFluidizedBed 3.4
            --history DEM/post/bed.dat:3.41:5e-3
            --summary results/summary.dat:0:0.025 -- -ci)
set_tests_properties(continuation.liquidFluidizedBed PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300
    FIXTURES_REQUIRED liquidFluidizedBed_ci)
