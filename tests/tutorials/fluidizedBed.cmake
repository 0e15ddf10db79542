# fluidizedBed tests (FOAMDEM_WORK and TUT come from integration.cmake)

# fluidizedBed, CI variant (4000 particles, short sweep): fluidised-bed
# pressure drop within 7 % of the buoyant bed weight per area (3 x the
# 2.3 % spread of five realisations), U_mf of the increasing sweep within
# 10 % of Ergun at the initial voidage (six realisations: +0.7 to +3.6 %;
# the decreasing branch of the short sweep does not always settle and is
# reported only), no particle lost, void fraction never clipped (validate.py
# --ci; tutorials/fluidizedBed/README.md, "CI checks"). About 2-3 min on
# one free core.
add_test(NAME fluidizedBed.ci
    COMMAND ${TUT} fluidizedBed ${FOAMDEM_WORK}/fluidizedBed -ci)
set_tests_properties(fluidizedBed.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_SETUP fluidizedBed_ci)

# Continuation (issue 15 part 2): a copy of the CI run (fluidizedBed.ci)
# without its writes after 1.6 s (in the decreasing sweep), continued by
# ./Allrun -ci -continue (the fields and DEM/restart/1.6.restart;
# validate.py over the joined bed.dat and postProcessing/*/0 and /1.6,
# which must pass). The bed's history 5 ms after the restart agrees with
# the straight run's to 1e-3 (measured: mean height 6.6e-8, maximum 4.0e-7,
# kinetic energy 8.6e-6, floor and side-wall forces 1.3e-5 and 1.5e-4; the
# fields are read back from 8 ASCII digits, and the bubbling bed amplifies
# that); then the runs part, so results/summary.dat is compared
# statistically: the minimum fluidisation velocities of the two sweeps
# within 8 % and the voidage at U_mf within 0.02 (results/summary.dat).
# Two realisations measured: U_mf of the decreasing sweep -1.0 % and
# -3.8 % (1.2079 against 1.2557 m/s, 2026-12-04, the fit taking 17
# points instead of 18), voidage at U_mf -0.003 and -0.005; everything
# before 1.6 s, the plateau included, identical. The fit-derived error
# figures (UmfErrorWenYu, fixedBedErrorErgun) jump with the fit's point
# count (0.181 against 0.136) and are not compared; the tutorial's own
# checks (Allrun's exit status) must pass on the continued run.
# Seen failing with DEM/in.liggghts reading DEM/post/packed.restart instead
# of ${foamDEMRestart}. About 20 s on the CI run.
set(CONTINUATION_TUT ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialContinuation)
add_test(NAME continuation.fluidizedBed
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/fluidizedBed
            ${FOAMDEM_WORK}/continuation_fluidizedBed 1.6
            --history DEM/post/bed.dat:1.605:1e-3
            --summary results/summary.dat:0.08:0:Umf_decreasing_m_s,Umf_increasing_m_s
            --summary results/summary.dat:0:0.02:voidage_mf -- -ci)
set_tests_properties(continuation.fluidizedBed PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300
    FIXTURES_REQUIRED fluidizedBed_ci)

# No np 2 continuation test: the CI run's checks depend on the realisation
# of its bubbling bed (2026-12-05, four realisations of ./Allrun -ci: np 1
# as written (8 digits) passes, plateau +0.6 %, U_mf (decreasing) 1.256
# m/s; the same at 17 written digits, whose initial fields differ by 1e-16,
# fails with U_mf 2.25 m/s (voidage on the decreasing branch's fixed-bed
# part 0.507: the compressed sweep leaves the bed loose); -n 4001 fails
# with U_mf 2.02 m/s; np 2 fails the plateau, -4.0 % against the 2 % bound).
# The CI's sweep is too fast for a quasi-static defluidisation; the
# tutorial README says so. Those were the full run's checks, which the CI
# used then; since 2026-12-05 validate.py --ci checks the increasing
# branch's U_mf (10 %) and the plateau within 7 %, which all six measured
# realisations pass (README, "CI checks"), so an np 2 continuation test
# would now be possible; it has not been added.


# The volume-weighted particle velocity Us (output only) is averaged at
# write times only (issue 13: nothing computed that a scene does not use):
# at every write of the CI run it equals sum V_i v_i / sum V_i over the
# particles of the written cloud in each cell (the centre void fraction),
# to the files' precision (measured up to 2.1e-8 of the largest speed from
# the 8 written digits), and the
# log says so. Seen failing with the average never taken (Us zero at the
# writes). Seconds, on the CI run's output.
add_test(NAME fluidizedBed.UsAtWriteTimes
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkUsAverage
            ${FOAMDEM_WORK}/fluidizedBed)
set_tests_properties(fluidizedBed.UsAtWriteTimes PROPERTIES
    LABELS integration TIMEOUT 60 FIXTURES_REQUIRED fluidizedBed_ci)
