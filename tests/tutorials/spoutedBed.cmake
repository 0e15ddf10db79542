# spoutedBed tests (FOAMDEM_WORK and TUT come from integration.cmake)

# CI variant (1 713 shaped spheres of the 35 % set, schedule compressed to
# 0.44 s, k-epsilon): the inlet follows the schedule table (1e-6 m/s), the
# pressure probe has a sample every CFD step, the plateau analysis gives
# finite values for all five plateaus, no particle is lost and the mass is
# constant (postprocess.py --ci)
add_test(NAME spoutedBed.ci
    COMMAND ${TUT} spoutedBed ${FOAMDEM_WORK}/spoutedBed -ci)
set_tests_properties(spoutedBed.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_SETUP spoutedBed_ci)

# The run's last step is written, also off the write grid (the solver's
# foamDEM::writeAtEndTime): the CI schedule ends at 0.44 s, between the
# 0.1 s writes, and the CI run has the fields and the DEM restart of 0.44 s
# to continue from. Seen failing without that call in pisoDEMFoam (the
# latest write 0.4 s)
add_test(NAME spoutedBed.endWrite
    COMMAND sh -c "cd ${FOAMDEM_WORK}/spoutedBed && test -f 0.44/U && test -f DEM/restart/0.44.restart && echo 'written at 0.44 s: fields and DEM restart'")
set_tests_properties(spoutedBed.endWrite PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 30 FIXTURES_REQUIRED spoutedBed_ci)

# The same at np 2: the DEM and the mesh cut across the width through the
# spout; the shaped spheres' orientations move with them between ranks
add_test(NAME parallel.spoutedBed.ci
    COMMAND ${TUT} spoutedBed ${FOAMDEM_WORK}/spoutedBed_np2 -ci -np 2)
set_tests_properties(parallel.spoutedBed.ci PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2)

# The shaped spheres' drag (verification): one sphere of a plate's volume,
# spinning at 20 rad/s, settles with the plate's Hoelzer-Sommerfeld drag at
# its turning orientation; its velocity matches a Python ODE with a second
# implementation of the orientation (random start for id 1, turned by the
# spin) within 1 % (measured 0.13 %). Fails with the orientation not turned
# (24.6 %, checked), and the script requires the identity orientation and
# the sphere drag to be told apart (13 % and 84 %)
add_test(NAME shapedSpheres.settlingPlate
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkShapedSphere
            ${FOAMDEM_WORK}/shapedSpheres_settlingPlate)
set_tests_properties(shapedSpheres.settlingPlate PROPERTIES
    LABELS "integration" TIMEOUT 300)

# Continuation (issue 15 part 2, the library's mechanism as in every other
# tutorial): a copy of the CI run without its writes after 0.2 s,
# continued by ./Allrun -ci -continue from the fields and the library's
# DEM restart of 0.2 s (DEM/restart/0.2.restart, read by the DEM script
# through foamDEMRestart) to the end (0.44 s); the checks pass on the
# joined output (the probe files and the 100 Hz heights are joined, the
# later segment replacing the earlier), and the 100 Hz row at 0.21 s (42
# coupling steps later: time, highest particle, count, mass) agrees with
# the straight run's to 1e-9 relative (measured 5.9e-12, 2026-12-04; the
# fields are read back from 8 digits). Seen failing with the DEM script
# reading the fill's restart: the solver refuses the run (step check)
set(CONTINUATION_TUT ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialContinuation)
add_test(NAME spoutedBed.continue
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/spoutedBed
            ${FOAMDEM_WORK}/spoutedBed_continue 0.2
            --history DEM/post/height.dat:0.21:1e-9
            -- -ci)
set_tests_properties(spoutedBed.continue PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_REQUIRED spoutedBed_ci)

# Another realisation of the bed (./Allrun -ci -realisation 1: another
# seed for the insertion) against the CI run, realisation 0: the
# tutorial's checks pass; the same bed (1 713 particles, each shape's
# count and the mass realisation 0's) inserted otherwise (the fill's
# highest centre 26 %, its kinetic energy 67 %, the first 100 Hz row's
# highest particle 27 % from realisation 0's, 2026-12-06). Seen failing
# with realisation 0's seed kept for every realisation (the bed is then
# realisation 0's to the last digit) and with the distribution's seed
# changed too (the mass 8.5e-4 from realisation 0's, the counts differ)
add_test(NAME spoutedBed.realisation
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkRealisation
            ${FOAMDEM_WORK}/spoutedBed ${FOAMDEM_WORK}/spoutedBed_realisation 1
            -- -ci)
set_tests_properties(spoutedBed.realisation PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_REQUIRED spoutedBed_ci)

# A run continued on more processes than it ran on (the plates run went
# from np 1 to np 2 at 3.5 s): the np 1 CI run continued from its 0.2 s
# write by ./Allrun -ci -np 2 -continue, which decomposes that write; the
# solver runs on 2 processes and the 100 Hz row 0.01 s later agrees with
# the np 1 run's to 1e-6 relative (measured 8.6e-9 for the highest
# particle, 6.8e-14 for the mass, 2026-12-06: a different summation
# order). Seen failing with Allrun's decomposition on continue removed (the
# solver ran on 1 process)
add_test(NAME parallel.spoutedBed.continueNp2
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/spoutedBed
            ${FOAMDEM_WORK}/spoutedBed_continueNp2 0.2
            --history DEM/post/height.dat:0.21:1e-6 --nprocs 2
            -- -ci -np 2)
set_tests_properties(parallel.spoutedBed.continueNp2 PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_REQUIRED spoutedBed_ci)

# The fidelity representation (clumps: multisphere bodies of spheres of
# the plates' 0.33 mm thickness and the rods' diameter, explicit drag on
# the bodies), 1 % of the 35 % set's particles at np 2 through the CI
# variant's compressed schedule: the fill inserts the bodies at random
# orientations, the coupled run reads them from the fill's restart, and
# postprocess.py --ci checks the schedule, the probe, the analysis, the
# body count (inserted = the set's, from the first snapshot's spheres per
# type) and that no sphere is lost and the mass is constant
add_test(NAME parallel.spoutedBed.clumps
    COMMAND ${TUT} spoutedBed ${FOAMDEM_WORK}/spoutedBed_clumps -ci -np 2
            -representation clumps -fraction 0.01)
set_tests_properties(parallel.spoutedBed.clumps PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_SETUP spoutedBed_clumps)

# Continuation of the clumps (a fidelity run spans sessions): that run
# continued from its 0.2 s write at np 2 (the bodies' state comes from
# fix multisphere's part of the library's DEM restart, matched by the
# fix's ID); the 100 Hz row 0.01 s later (highest sphere, sphere count,
# mass) agrees with the straight run's to 1e-9 relative (measured 6.2e-12,
# 2026-12-06). Seen failing with the coupled script's fix renamed (ms2:
# the bodies' state not read): the count and the mass differ by 100 %
# and ./Allrun -continue fails
add_test(NAME parallel.spoutedBed.clumps.continue
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/spoutedBed_clumps
            ${FOAMDEM_WORK}/spoutedBed_clumps_continue 0.2
            --history DEM/post/height.dat:0.209984667056107:1e-9
            -- -ci -np 2)
set_tests_properties(parallel.spoutedBed.clumps.continue PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_REQUIRED spoutedBed_clumps)

# A fidelity run carried to another machine as its bodies' states (its
# LIGGGHTS restarts are about 300 MB a write; multisphereBodies.H): the
# clumps run above, its writes after 0.2 s removed, packed by
# foamDEMArchiveRun pack --bodies (DEM/restart/0.2.restart left out,
# 0.2.bodies kept) and unpacked; ./Allrun -continue rebuilds
# DEM/restart/0.2.restart from 0.2.bodies on one process (the bodies
# inserted again type by type, set from the file) and continues at np 2.
# The dump the continued run writes at its first step holds the straight
# run's 8 500 spheres at 0.2 s (as sets: IDs are new) to the dump's six
# significant digits (1e-6 m; measured 0, 2026-12-07), and 0.01 s later
# the 100 Hz row agrees with the straight run's to 1e-4 relative (measured:
# count and mass equal, highest sphere 5.9e-7: the rebuilt state has no
# contact history; the full restart's continuation above gives 6.2e-12);
# the tutorial's checks pass over both segments.
add_test(NAME parallel.spoutedBed.clumps.bodies
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/spoutedBed_clumps
            ${FOAMDEM_WORK}/spoutedBed_clumps_bodies 0.2 --bodies
            --same-spheres DEM/post/dump/snap.{step}.txt:1e-6
            --history DEM/post/height.dat:0.209984667056107:1e-4
            -- -ci -np 2)
set_tests_properties(parallel.spoutedBed.clumps.bodies PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_REQUIRED spoutedBed_clumps)

# A fill stopped by a kill and continued (the full-bed fidelity fill takes
# longer than a session): the clumps run above, its fill started again,
# killed (process group, SIGKILL) once it has written its first restart
# (DEM/post/fill.restart, renamed into place after each segment) and
# continued by ./Allrun -continue; the continued fill starts after step 1
# from that restart and its FILL line (spheres, kinetic energy, highest
# centre) equals the straight fill's exactly (measured 0, 2026-12-06: same
# segments, same restarts), and the coupled run and its checks pass. Seen
# failing with the continued fill's multisphere fix renamed (the bodies
# not read): LIGGGHTS stops, no FILL line
add_test(NAME parallel.spoutedBed.clumps.fillContinue
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkFillContinuation
            ${FOAMDEM_WORK}/spoutedBed_clumps ${FOAMDEM_WORK}/spoutedBed_clumps_fill
            -- -ci -np 2 -representation clumps -fraction 0.01)
set_tests_properties(parallel.spoutedBed.clumps.fillContinue PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_REQUIRED spoutedBed_clumps)

# The same fill carried to another machine while it settles (the
# full-bed fidelity fill takes 2.4-4.3 h, more than a session): killed
# after its first restart, ./Allrun -fillBodies writes that restart's
# bodies' states, foamDEMArchiveRun pack --bodies leaves the restart out,
# and ./Allrun -continue after unpack rebuilds DEM/post/fill.restart from
# DEM/post/fill.bodies, continues the fill at np 2 and runs the coupled
# stage and its checks. The first thermo row after the restart (303 steps
# on: spheres, kinetic energy, highest centre) agrees with the straight
# fill's to 1e-3 relative (measured 0, 1.2e-5 and 0, 2026-12-07); the end
# of the fill is another realisation (no contact history; highest centre
# 12.8 against 23.8 mm), printed only. Seen failing with the bodies'
# centres of mass not set from the file (the row 7.8e-2 off)
add_test(NAME parallel.spoutedBed.clumps.fillBodies
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkFillContinuation
            ${FOAMDEM_WORK}/spoutedBed_clumps ${FOAMDEM_WORK}/spoutedBed_clumps_fillBodies
            --bodies --rtol 1e-3
            -- -ci -np 2 -representation clumps -fraction 0.01)
set_tests_properties(parallel.spoutedBed.clumps.fillBodies PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2
    FIXTURES_REQUIRED spoutedBed_clumps)

# The lift and torque variants (Allrun -lift on -torque on; off in the
# reference): the clumps CI run at np 2 with Saffman-Mei and Magnus lift,
# pitching torque and rotational drag on the bodies of all six shapes. The
# four models are selected (checkForceModels: seen failing on a log without
# the variant), the tutorial's checks pass (no body lost, mass constant,
# schedule, probe rate, analysis), and at every coupling step the force on
# the particles equals minus the fluid's momentum source to 1e-10 (the
# lift's reaction included; measured 1.2e-15, 2026-12-07). 169 s. Seen
# failing with the fluid's share of the coupled force halved in
# implicitCoupling.C: worst mismatch 0.037 over 1 884 coupling steps
# (2026-12-07)
set(SPOUTED_VARIANT ${FOAMDEM_WORK}/spoutedBed_liftTorque)
add_test(NAME parallel.spoutedBed.clumps.liftTorque
    COMMAND sh -c "${CMAKE_CURRENT_SOURCE_DIR}/integration/runVariant spoutedBed ${SPOUTED_VARIANT} true -ci -np 2 -representation clumps -fraction 0.01 -lift on -torque on && ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkForceModels ${SPOUTED_VARIANT}/log.pisoDEMFoam hoelzerSommerfeld saffmanMeiLift magnusLift pitchingTorque rotationalDrag && ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkMomentumBalance ${SPOUTED_VARIANT}/log.pisoDEMFoam 1e-10")
set_tests_properties(parallel.spoutedBed.clumps.liftTorque PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 900 PROCESSORS 2)

# The mesh check's start (Allrun -mapFrom SOURCE TIME): the CI run's 0.2 s
# state (its DEM restart, its fields mapped by mapFields -consistent, its
# history to 0.2 s) continued on a mesh with 20 cells across instead of 16
# (6 560 cells, not 5 248); the tutorial's checks pass over the joined
# history, the solver continued from DEM/restart/0.2.restart, and 0.01 s
# later the 100 Hz row (highest particle, count, mass) is within 1e-2 of
# the source's (measured 2.7e-4, 2026-12-06). Seen failing with mapFields
# left out (the time directory a copy of 0/): the solver stops with NaN in
# its first steps
add_test(NAME spoutedBed.mapFrom
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkTutorialMapFrom
            spoutedBed ${FOAMDEM_WORK}/spoutedBed ${FOAMDEM_WORK}/spoutedBed_mapFrom 0.2
            --set ciNWidth=20 --history DEM/post/height.dat:0.21:1e-2
            -- -ci)
set_tests_properties(spoutedBed.mapFrom PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_REQUIRED spoutedBed_ci FIXTURES_SETUP spoutedBed_mapFrom)

# A run started by -mapFrom has no fill of its own: ./Allrun -continue
# takes its write as the fill's end (the run above, its writes after 0.3 s
# removed, continued to the end; the 100 Hz row at 0.31 s agrees with the
# straight run's to 1e-9, measured 8.3e-11, 2026-12-06). Seen failing with
# that rule removed from Allrun: it looks for the fill's restart and stops
add_test(NAME spoutedBed.mapFrom.continue
    COMMAND ${CONTINUATION_TUT} ${FOAMDEM_WORK}/spoutedBed_mapFrom
            ${FOAMDEM_WORK}/spoutedBed_mapFrom_continue 0.3
            --history DEM/post/height.dat:0.31:1e-9
            -- -ci)
set_tests_properties(spoutedBed.mapFrom.continue PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_REQUIRED spoutedBed_mapFrom)
