# liquidFluidizedBed tests (FOAMDEM_WORK and TUT come from integration.cmake)

# CI variant: the bed of 2 500 1 mm glass spheres in water at two
# velocities (Richardson-Zaki voidage 0.8 and 0.6), the law with the best
# documented agreement, |eps - eps_RZ| within the bound stated in Allrun
# (Richardson & Zaki with Brown & Lawler's U_t and Garside & Al-Dibouni's
# n: an independent reference). About 2-3 min on one free core.
add_test(NAME liquidFluidizedBed.ci
    COMMAND ${TUT} liquidFluidizedBed ${FOAMDEM_WORK}/liquidFluidizedBed -ci)
set_tests_properties(liquidFluidizedBed.ci PROPERTIES
    LABELS "integration;tutorial;validation" TIMEOUT 900
    FIXTURES_SETUP liquidFluidizedBed_ci)

# Continuation (issue 15 part 2): a copy of the CI run (liquidFluidizedBed.ci)
# without its writes after 3.4 s (near the end of the first stage's hold),
# continued by ./Allrun -ci -continue (the fields and
# DEM/restart/3.4.restart; validate.py over the joined bed.dat,
# heights.dump and postProcessing/inlet/0 and /3.4, which must pass). The
# bed's history 10 ms after the restart agrees with the straight run's to
# 1e-5 (measured: mean height 5.0e-6, maximum 4.5e-7, kinetic energy
# 4.9e-4 with the fields read back from 8 ASCII digits; 3.2e-11, 2.1e-11
# and 1.3e-7 since the tutorial writes 17; the bound was 5e-3); then the runs
# part, and results/summary.dat is compared statistically, stage by stage
# (the lines of eps_aimed 0.8 and 0.6). The first stage's numbers within
# 1e-3 absolute: the restart is near its end (voidage 0.788492
# against 0.788484). The second stage's within 0.065: its voidage is one
# realisation of a chaotic bed over a short window; four realisations
# (2026-12-05: np 1 straight 0.5939 and continued 0.5860, np 2 straight
# 0.6197 and continued 0.5895) have a standard deviation of 0.015, so two
# of them differ by up to about 3 x sqrt(2) x 0.015 = 0.065 (the bound was
# 0.025 for every number, and the np 2 pair differed by 0.030). Seen failing with DEM/in.liggghts
# reading DEM/post/packed.restart instead of ${foamDEMRestart} (the packed
# bed under the expanded bed's flow: lost atoms at 3.432 s). About 30 s on
# the CI run.
set(CONTINUATION_TUT ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialContinuation)
add_test(NAME continuation.liquidFluidizedBed
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/liquidFluidizedBed
            ${FOAMDEM_WORK}/continuation_liquidFluidizedBed 3.4
            --history DEM/post/bed.dat:3.41:1e-5
            --summary results/summary.dat:0:1e-3:0.8
            --summary results/summary.dat:0:0.065:0.6 -- -ci)
set_tests_properties(continuation.liquidFluidizedBed PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300
    FIXTURES_REQUIRED liquidFluidizedBed_ci)

# No np 2 continuation test: the tutorial's own CI check (|eps - eps_RZ| <=
# 0.02, Allrun) depends on the realisation at np 2 (2026-12-05: the np 2 CI
# run's second stage +0.0197, inside the bound by 0.0003; realisations
# scatter by 0.015), and the continued run must pass it as well. Measured
# once (not a test): np 2 continued from 3.4 s, bed history at 3.41 s
# within 6.3e-10, second-stage voidage 0.5895 against 0.6197.
