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
# 4.9e-4 with the fields read back from 8 ASCII digits; 3.2e-11, 2.1e-11
# and 1.3e-7 since the tutorial writes 17); then the runs
# part, and results/summary.dat is compared statistically: every number
# within 0.06 absolute. The second stage's voidage is one realisation of a
# chaotic bed over a short window: four realisations (2026-12-05: np 1
# straight 0.5939 and continued 0.5860, np 2 straight 0.6197 and continued
# 0.5895) have a standard deviation of 0.015, so two of them differ by
# up to about 3 x 0.021 = 0.06 (the bound was 0.025 and the np 2 pair
# differed by 0.030). The first stage's voidage agrees to 1e-5 (0.788492
# against 0.788484), as the restart is near the stage's end. Seen failing with DEM/in.liggghts
# reading DEM/post/packed.restart instead of ${foamDEMRestart} (the packed
# bed under the expanded bed's flow: lost atoms at 3.432 s). About 30 s on
# the CI run.
set(CONTINUATION_TUT ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialContinuation)
add_test(NAME continuation.liquidFluidizedBed
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/liquidFluidizedBed
            ${FOAMDEM_WORK}/continuation_liquidFluidizedBed 3.4
            --history DEM/post/bed.dat:3.41:5e-3
            --summary results/summary.dat:0:0.06 -- -ci)
set_tests_properties(continuation.liquidFluidizedBed PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300
    FIXTURES_REQUIRED liquidFluidizedBed_ci)

# The same at np 2 (issue 15: the continuation of every tutorial, in
# parallel too): the CI run at np 2 (its own checks must pass), then its
# copy continued from 3.4 s with ./Allrun -ci -np 2 -continue, with the
# bounds above (bed history at 3.41 s: 6.3e-10 at most). Seen failing with
# the straight run's DEM script reading DEM/post/packed.restart: the
# checker names the file read, the continued run stops
add_test(NAME liquidFluidizedBed.np2
    COMMAND ${TUT} liquidFluidizedBed ${FOAMDEM_WORK}/liquidFluidizedBed_np2 -ci -np 2)
set_tests_properties(liquidFluidizedBed.np2 PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_SETUP liquidFluidizedBed_np2)
add_test(NAME continuation.liquidFluidizedBed.np2
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/liquidFluidizedBed_np2
            ${FOAMDEM_WORK}/continuation_liquidFluidizedBed_np2 3.4
            --history DEM/post/bed.dat:3.41:5e-3
            --summary results/summary.dat:0:0.06 -- -ci -np 2)
set_tests_properties(continuation.liquidFluidizedBed.np2 PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 300 PROCESSORS 2
    FIXTURES_REQUIRED liquidFluidizedBed_np2)
