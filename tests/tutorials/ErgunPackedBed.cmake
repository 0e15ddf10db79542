# ErgunPackedBed tests (FOAMDEM_WORK and TUT come from integration.cmake)

# Pressure drop inside a frozen bed of 3000 spheres within 2 % of Ergun with
# the bed's measured void fraction, at three velocities below U_mf
add_test(NAME ErgunPackedBed.ci
    COMMAND ${TUT} ErgunPackedBed ${FOAMDEM_WORK}/ErgunPackedBed -ci)
set_tests_properties(ErgunPackedBed.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300
    FIXTURES_SETUP ErgunPackedBed_ci)

# The same on 2 processes (./Allrun -ci -np 2): packing by foamDEMLiggghts
# on 2 ranks, decomposePar (slabs up the column), mpirun, reconstructPar;
# the same 2 % check (the bed packed on 2 ranks is another bed: 1.5 %
# measured, 1.1 % at np 1). About 30 s on 2 loaded cores.
add_test(NAME ErgunPackedBed.np2
    COMMAND ${TUT} ErgunPackedBed ${FOAMDEM_WORK}/ErgunPackedBed_np2 -ci -np 2)
set_tests_properties(ErgunPackedBed.np2 PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 300 PROCESSORS 2
    FIXTURES_SETUP ErgunPackedBed_np2)

# The same with Euler's default flux ddt correction and a small time step:
# guards the eps_f factor of pisoDEMFoam's ddtCorr term (without it the
# steady pressure drop depended on deltaT and was ~40 % low at this step)
add_test(NAME ErgunPackedBed.ddtCorr
    COMMAND ${TUT} ErgunPackedBed ${FOAMDEM_WORK}/ErgunPackedBed_ddtCorr
            -ci -ddt Euler -dt 2.5e-4)
set_tests_properties(ErgunPackedBed.ddtCorr PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300)

# Inlet semantics: the same frozen bed resting on the inlet (-floor 0) and
# above a one-cell (6 mm) empty distributor layer. Each run checks that the
# superficial inflow (alphaPhi over the inlet / A) equals the inlet velocity
# to round-off and that the pressure drop inside the bed matches the
# prediction (Gidaspow: Ergun, within 2 %; Koch-Hill: its own uniform-bed
# prediction, a verification); compareBedFloors then asks for the same
# pressure drop on and above the inlet within 1 %. With the void fraction
# zeroGradient at the inlet the bed on the inlet gets 0.42 x U and its
# pressure drop is 66-72 % lower.
set(CMP_FLOORS ${CMAKE_CURRENT_SOURCE_DIR}/integration/compareBedFloors)
foreach(law gidaspow kochHill)
    foreach(floor onInlet distributor)
        if(floor STREQUAL onInlet)
            set(z 0)
        else()
            set(z 0.006)
        endif()
        add_test(NAME ErgunPackedBed.${law}.${floor}
            COMMAND ${TUT} ErgunPackedBed ${FOAMDEM_WORK}/ErgunPackedBed_${law}_${floor}
                    -ci -floor ${z} -drag ${law})
        set_tests_properties(ErgunPackedBed.${law}.${floor} PROPERTIES
            LABELS "integration;tutorial" TIMEOUT 300
            FIXTURES_SETUP ErgunPackedBed_${law}_floors)
    endforeach()
    add_test(NAME ErgunPackedBed.${law}.sameOnInlet
        COMMAND ${CMP_FLOORS} ${FOAMDEM_WORK}/ErgunPackedBed_${law}_onInlet
                ${FOAMDEM_WORK}/ErgunPackedBed_${law}_distributor 0.01)
    set_tests_properties(ErgunPackedBed.${law}.sameOnInlet PROPERTIES
        LABELS "integration;tutorial" TIMEOUT 60
        FIXTURES_REQUIRED ErgunPackedBed_${law}_floors)
endforeach()

# The user's void fraction boundary conditions: an interstitial inlet
# (0/voidfraction zeroGradient on the inlet) under a bed on the inlet is
# read from the file and the stability guard reports the superficial
# inflow it implies (0.42 x U)
add_test(NAME ErgunPackedBed.interstitialInletGuard
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkInterstitialInlet
            ${FOAMDEM_WORK}/ErgunPackedBed_interstitialInlet)
set_tests_properties(ErgunPackedBed.interstitialInletGuard PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300)

# Continuation (issue 15 part 2): a copy of the CI run (ErgunPackedBed.ci,
# np 1, and ErgunPackedBed.np2) without its writes after 0.045 s, continued
# by ./Allrun -ci -continue (the fields and DEM/restart/0.045.restart, then
# validate.py over both segments), agrees with the run straight through at
# 0.09 s: p, U, voidfraction and the particle positions to 1e-10 relative
# (measured np 1: p 3.4e-14, U 5.6e-13, the bed and results/summary.dat
# identical; the fields are read back from 10 ASCII digits), summary.dat
# to 1e-9. The frozen bed is the same whichever restart the DEM reads, so
# the check also asks that the DEM script read DEM/restart/0.045.restart
# (log.liggghts). Seen failing with DEM/in.liggghts reading
# DEM/post/packed.restart instead of ${foamDEMRestart}. A few seconds each.
set(CONTINUATION_TUT ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialContinuation)
add_test(NAME continuation.ErgunPackedBed
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/ErgunPackedBed
            ${FOAMDEM_WORK}/continuation_ErgunPackedBed 0.045
            --field 0.09:p,U,voidfraction,lagrangian/particles/positions:1e-10
            --summary results/summary.dat:1e-9 -- -ci)
set_tests_properties(continuation.ErgunPackedBed PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 120
    FIXTURES_REQUIRED ErgunPackedBed_ci)
add_test(NAME continuation.ErgunPackedBed.np2
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/ErgunPackedBed_np2
            ${FOAMDEM_WORK}/continuation_ErgunPackedBed_np2 0.045
            --field 0.09:p,U,voidfraction,lagrangian/particles/positions:1e-10
            --summary results/summary.dat:1e-9 -- -ci -np 2)
set_tests_properties(continuation.ErgunPackedBed.np2 PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 120 PROCESSORS 2
    FIXTURES_REQUIRED ErgunPackedBed_np2)
