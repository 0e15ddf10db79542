# settlingSphere tests (FOAMDEM_WORK and TUT come from integration.cmake)
set(VARIANT ${CMAKE_CURRENT_SOURCE_DIR}/integration/runVariant)
set(BALANCE ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkMomentumBalance)
set(CP constant/couplingProperties)

# Terminal velocity within 0.5 % of the ODE, per single-particle drag law
foreach(law schillerNaumann diFelice kochHill gidaspow beetstra tenneti rong)
    add_test(NAME settlingSphere.${law}
        COMMAND ${TUT} settlingSphere ${FOAMDEM_WORK}/settlingSphere_${law}
                -ci -drag ${law})
    set_tests_properties(settlingSphere.${law} PROPERTIES
        LABELS "integration;tutorial" TIMEOUT 300
        FIXTURES_SETUP settling_${law})
endforeach()

# The same check with explicit coupling and with model B; each run logs the
# momentum exchange at every coupling step
add_test(NAME settlingSphere.explicitCoupling
    COMMAND ${VARIANT} settlingSphere ${FOAMDEM_WORK}/settlingSphere_explicit
            "foamDictionary ${CP} -entry momentumCoupling -set explicit && foamDictionary ${CP} -entry progressInterval -add 30" -ci)
add_test(NAME settlingSphere.modelB
    COMMAND ${VARIANT} settlingSphere ${FOAMDEM_WORK}/settlingSphere_modelB
            "foamDictionary ${CP} -entry modelType -set B && sed -i 's/ archimedes pressureGradient)/ archimedes)/' Allrun"
            -ci -drag schillerNaumann)
set_tests_properties(settlingSphere.explicitCoupling PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300 FIXTURES_SETUP settling_explicit)
set_tests_properties(settlingSphere.modelB PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300 FIXTURES_SETUP settling_modelB)

# couplingKernel cellPoint (u_f and eps interpolated at the particle; the
# fluid's implicit term sees the cell's U, the rest of the reaction goes
# explicitly): terminal velocity within 0.5 % (measured +0.21 %; the cell
# kernel +0.26 %), and the momentum balance below, seen failing (a
# mismatch of 3.9e-3) without the explicit share
add_test(NAME settlingSphere.cellPoint
    COMMAND ${VARIANT} settlingSphere ${FOAMDEM_WORK}/settlingSphere_cellPoint
            "foamDictionary ${CP} -entry couplingKernel -add cellPoint" -ci)
set_tests_properties(settlingSphere.cellPoint PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300 FIXTURES_SETUP settling_cellPoint)

# Bookkeeping (verification, not a measurement): the coupled forces on the
# particles and the fluid's source, summed at the same instant from the
# same coefficients, agree to 1e-10 (implicit model B run, explicit
# coupling); the measured exchange is impulseBalance.* below
foreach(v explicit modelB cellPoint)
    add_test(NAME momentumBalance.${v}
        COMMAND ${BALANCE} ${FOAMDEM_WORK}/settlingSphere_${v}/log.pisoDEMFoam 1e-10)
    set_tests_properties(momentumBalance.${v} PROPERTIES
        LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_${v})
endforeach()

# The exchange measured (tests/integration/checkImpulseBalance): the DEM
# particles' impulse from the fluid over each coupling interval (momentum
# change less gravity and the uncoupled forces) against the fluid's coupled
# impulse in its step. After the start-up (0.1 s) each interval within 1e-2
# (the coupling's one-step lag: 6.2e-3 when the sphere crosses a cell
# face, implicit drag; 5.7e-4 explicit), summed over the run within 3e-3
# (measured 1.5e-3 implicit, 2.2e-5 explicit). A DEM that applied 0.98 of
# the pushed K_p: 2.6e-2 and 1.9e-2, failed (the test above: 4e-16)
set(IMPULSE ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkImpulseBalance)
foreach(v explicit modelB magnus)
    add_test(NAME impulseBalance.${v}
        COMMAND ${IMPULSE} ${FOAMDEM_WORK}/settlingSphere_${v}/log.pisoDEMFoam 0.1 1e-2 3e-3)
    set_tests_properties(impulseBalance.${v} PROPERTIES
        LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_${v})
endforeach()

# Progress lines (runProgress.H) against the solver's own log: one every
# progressInterval steps (default 100; 30 in the explicit variant), at the
# solver's time of that step and its fraction of endTime, the split adding
# up to 100 %, the final summary's DEM share the timers' DEM time.
# Seen failing with the line's time taken one step late (t + deltaT)
set(PROGRESS ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkProgress)
add_test(NAME progress.default
    COMMAND ${PROGRESS} ${FOAMDEM_WORK}/settlingSphere_schillerNaumann/log.pisoDEMFoam 100)
add_test(NAME progress.interval30
    COMMAND ${PROGRESS} ${FOAMDEM_WORK}/settlingSphere_explicit/log.pisoDEMFoam 30)
set_tests_properties(progress.default PROPERTIES
    LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_schillerNaumann)
set_tests_properties(progress.interval30 PROPERTIES
    LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_explicit)

# Particles written as a lagrangian cloud that foamToVTK exports
add_test(NAME particleOutput.foamToVTK
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkParticleVTK
            ${FOAMDEM_WORK}/settlingSphere_schillerNaumann 1)
set_tests_properties(particleOutput.foamToVTK PROPERTIES
    LABELS integration TIMEOUT 120 FIXTURES_REQUIRED settling_schillerNaumann)

# Demand-driven exchange: two scenes, two plans. Implicit drag pulls
# velocities and pushes K_p and u_f; explicit coupling pushes only a force.
# Neither pulls spin or density.
add_test(NAME exchangePlan.implicitDrag
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkExchangePlan
            ${FOAMDEM_WORK}/settlingSphere_schillerNaumann/log.pisoDEMFoam
            "position velocity radius id implicitCoeff fluidVelocity explicitForce"
            "angularVelocity density")
set_tests_properties(exchangePlan.implicitDrag PROPERTIES
    LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_schillerNaumann)
add_test(NAME exchangePlan.explicitDrag
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkExchangePlan
            ${FOAMDEM_WORK}/settlingSphere_explicit/log.pisoDEMFoam
            "position velocity radius id explicitForce"
            "implicitCoeff fluidVelocity angularVelocity density")
set_tests_properties(exchangePlan.explicitDrag PROPERTIES
    LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_explicit)

# The arrays the scenes allocated, as they log them (checkDEMArrays NAME
# FIXTURE PRESENT ABSENT [LINE]). Asked of LIGGGHTS (demArrays): implicit
# drag has K_p and u_f but no per-atom torque; explicit coupling has one
# force array (and the torque array couple/cfd/force reads), none of the
# implicit fix's. foamDEM's particle data after the first exchange
# (particleArrays): a drag-only scene has no spin, orientation, torque,
# type or density; explicit coupling has no K_p array
set(PARTICLE_ARRAYS "foamDEM particle arrays after the first exchange")
function(add_array_check name fixture present absent)
    add_test(NAME ${name}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkDEMArrays
                ${FOAMDEM_WORK}/settlingSphere_${fixture}/log.pisoDEMFoam
                "${present}" "${absent}" ${ARGN})
    set_tests_properties(${name} PROPERTIES
        LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_${fixture})
endfunction()
add_array_check(demArrays.implicitDrag schillerNaumann "dragforce Ksl uf" "hdtorque")
add_array_check(demArrays.explicitDrag explicit "dragforce" "Ksl uf KslRotation ex KslExtra")
add_array_check(particleArrays.implicitDrag schillerNaumann
    "position velocity radius implicitCoeff explicitForce"
    "angularVelocity orientation torque type density" "${PARTICLE_ARRAYS}")
add_array_check(particleArrays.explicitDrag explicit
    "position velocity radius explicitForce"
    "implicitCoeff angularVelocity orientation torque type density" "${PARTICLE_ARRAYS}")
add_array_check(particleArrays.magnusLift magnus
    "position velocity radius angularVelocity implicitCoeff"
    "orientation torque type density" "${PARTICLE_ARRAYS}")

# Parallel: the sphere's cell is on CFD rank 0 while LIGGGHTS holds it on
# rank 1, so it moves between ranks every step; np = 1 and np = 2 agree
add_test(NAME parallel.settlingSphere.np2
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/compareParallel
            ${FOAMDEM_WORK}/parallel_settling 2 1e-8
            "sed -i 's/^variable x0     equal 0.02$/variable x0     equal 0.012/' DEM/parameters")
set_tests_properties(parallel.settlingSphere.np2 PROPERTIES
    LABELS "integration;parallel" TIMEOUT 300 PROCESSORS 2)

# Parallel with the self-induced velocity correction (centre, cell kernel,
# undisturbedVelocity selfInducedCorrection), d/h = 0.25, the sphere on the
# rank cut (x = 20 mm): np = 1 and np = 2 agree to 1e-8. (The smoothed
# void fraction with a sphere at the cut differs between np 1 and np 2 by
# 4e-3 in velocity already without the new options, so the smoothed kernel
# is not compared here: see doc/validation.md)
add_test(NAME parallel.settlingSphere.undisturbedVelocity
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/compareParallel
            ${FOAMDEM_WORK}/parallel_settling_undisturbed 2 1e-8
            "foamDictionary constant/couplingProperties -entry undisturbedVelocity -add selfInducedCorrection && foamDictionary system/blockMeshDict -entry blocks -set '(hex (0 1 2 3 4 5 6 7) (10 10 40) simpleGrading (1 1 1))'"
            settlingSphere no)
set_tests_properties(parallel.settlingSphere.undisturbedVelocity PROPERTIES
    LABELS "integration;parallel" TIMEOUT 300 PROCESSORS 2)

# Work-precision report: three CFD steps, a table row each and the plot, and
# the documented trend (workPrecision.py TRENDS: the error is flat in the step
# and within 0.5 %) asserted by --check
add_test(NAME workPrecision.settlingSphere
    COMMAND ${CMAKE_COMMAND} -E env
            bash -c "${FOAMDEM_ROOT}/bin/foamDEMWorkPrecision ${FOAMDEM_ROOT}/tutorials/settlingSphere -o ${FOAMDEM_WORK}/workPrecision --levels dt4e-3,dt2e-3,dt1e-3 --check && test $(grep -c '^dt' ${FOAMDEM_WORK}/workPrecision/workPrecision.dat) -eq 3 && test -s ${FOAMDEM_WORK}/workPrecision/workPrecision.png")
set_tests_properties(workPrecision.settlingSphere PROPERTIES
    LABELS "integration;workPrecision" TIMEOUT 300)

# A scene with spin lift: the plan must now pull angular velocities, and the
# lift (a coupled force) keeps the momentum balance
add_test(NAME settlingSphere.magnusLift
    COMMAND ${VARIANT} settlingSphere ${FOAMDEM_WORK}/settlingSphere_magnus
            "foamDictionary ${CP} -entry forceModels -set '(schillerNaumann archimedes pressureGradient magnusLift)'"
            -ci)
set_tests_properties(settlingSphere.magnusLift PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300 FIXTURES_SETUP settling_magnus)
add_test(NAME exchangePlan.magnusLift
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkExchangePlan
            ${FOAMDEM_WORK}/settlingSphere_magnus/log.pisoDEMFoam
            "position velocity radius id angularVelocity implicitCoeff fluidVelocity explicitForce"
            "orientation type density")
add_test(NAME momentumBalance.magnusLift
    COMMAND ${BALANCE} ${FOAMDEM_WORK}/settlingSphere_magnus/log.pisoDEMFoam 1e-10)
set_tests_properties(exchangePlan.magnusLift momentumBalance.magnusLift PROPERTIES
    LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_magnus)

# Validation against experiments: schillerNaumann's terminal velocity at
# Re_t 10 and 300 within 1 % of Brown & Lawler's (2003) fit to measured
# drag (measured -0.38 % and -0.60 %), each run levelled off
add_test(NAME settlingSphere.terminalVelocity
    COMMAND ${TUT} settlingSphere ${FOAMDEM_WORK}/settlingSphere_terminal
            -terminal -ci)
set_tests_properties(settlingSphere.terminalVelocity PROPERTIES
    LABELS "integration;tutorial;validation" TIMEOUT 180)

# Continuation (issue 15 part 2): settlingSphere continued from its 0.1 s
# write (fields, gradp and DEM/restart/0.1.restart) agrees with the run
# straight through to 1e-12 at 0.2 and 0.25 s (measured: bitwise), and
# purgeWrite 2 removes the continued run's oldest write with its DEM
# restart. Seen failing: without the held forces put back, positions
# 1.3e-9 and velocities 5.4e-8 off; with the coupling terms pushed anew
# from the restart time's fluid, 3.2e-11 and 2.2e-10
# NAME.np1 and NAME.np2: SCRIPT WORK/<work>_np1 1 and WORK/<work>_np2 2
function(foamdem_np12_tests name script work)
    add_test(NAME ${name}.np1 COMMAND ${script} ${FOAMDEM_WORK}/${work}_np1 1)
    add_test(NAME ${name}.np2 COMMAND ${script} ${FOAMDEM_WORK}/${work}_np2 2)
    set_tests_properties(${name}.np1 PROPERTIES
        LABELS "integration;tutorial" TIMEOUT 300)
    set_tests_properties(${name}.np2 PROPERTIES
        LABELS "integration;tutorial;parallel" TIMEOUT 300 PROCESSORS 2)
endfunction()

set(CONTINUATION ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkContinuation)
foamdem_np12_tests(continuation.settlingSphere ${CONTINUATION} continuation)

# Stop signals (stopSignals.H, foamDEMStoppedEarly): settlingSphere -ci
# gets SIGUSR1 at its 0.05 s write (writes, goes on) and SIGUSR2 at its
# 0.1 s write (writes, stops; on np 2 sent to rank 1 only), then SIGUSR2
# to every rank every 20 ms until they end; Allrun exits 0 without
# post-processing, both writes have their DEM restart, and ./Allrun -ci
# -continue from the stop agrees with the run straight through to 1e-12
# at 0.25 s (measured: bitwise). Seen failing with the solver's
# stopSignals.check() taken out (no stop), and with settlingSphere's
# 'foamDEMStoppedEarly && exit 0' taken out (validate.py ran on the
# part-run, and passed)
foamdem_np12_tests(continuation.stopSignal
    ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkStopSignal stopSignal)

# The restart's periodic wrap: a sphere that crossed a periodic boundary
# since LIGGGHTS last built its neighbour list is outside the box at the
# write; the file must hold it wrapped, or read_restart drops it
# (checkContinuation --periodic: the sphere moves along a periodic x and
# the list is never rebuilt, so it is past the boundary at the 0.05 and
# 0.1 s writes; the continued run must agree to 1e-12 and the log must
# report the wrapped atom). Seen failing with the wrap taken out of
# liggghtsEngine::writeRestart: LIGGGHTS' 'Did not assign all atoms
# correctly' in the continued run.
add_test(NAME continuation.periodicWrap
    COMMAND ${CONTINUATION} ${FOAMDEM_WORK}/continuation_periodicWrap 1 --periodic)
set_tests_properties(continuation.periodicWrap PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300)

# Undisturbed fluid velocity (issue 12 item 4; ./Allrun -meshConvergence
# -ci, meshConvergence.py), each within 1 % of the ODE's terminal velocity
# with the same drag law (verification of the coupling: the reference is
# our own second implementation of the law, python/foamdem/drag.py):
#  1. d/h = 0.5 (20 x 20 x 80 mm box, 0.25 s), the tutorial's centre void
#     fraction and cell kernel with undisturbedVelocity
#     selfInducedCorrection (measured -0.63 %; without it +3.13 %);
#  2. d/h = 1 (12 x 12 x 60 mm box, 0.15 s), voidFraction smoothed (divided,
#     L = 2 d), couplingKernel voidFraction and the correction (measured
#     0.50 %; the tutorial as it is: 9.06 %).
# Seen failing with the correction switched off in the code: see
# doc/validation.md (settlingSphere as the cells shrink)
add_test(NAME settlingSphere.undisturbedVelocity
    COMMAND ${TUT} settlingSphere ${FOAMDEM_WORK}/settlingSphere_undisturbed
            -meshConvergence -ci)
set_tests_properties(settlingSphere.undisturbedVelocity PROPERTIES
    LABELS "integration;tutorial;verification" TIMEOUT 600)

# Newton's third law with the undisturbed-velocity treatment (bookkeeping,
# as momentumBalance.* above): d/h = 0.5 with the correction and the cell
# kernel (the fluid's implicit term at the velocity read plus the explicit
# -K_p (u_u - u_s), and the pressure-gradient part as a coupled force), and
# with the smoothed voidFraction kernel (the filter's symmetric matrix).
# Measured 3.8e-16 and 7.7e-15; seen failing without the explicit term
# (see doc/validation.md)
add_test(NAME momentumBalance.undisturbedVelocity
    COMMAND sh -c "w=${FOAMDEM_WORK}/momentumBalance_undisturbed && rm -rf $w && mkdir -p $w && cp -r ${FOAMDEM_ROOT}/tutorials/settlingSphere $w/case && cd $w/case && rm -rf results && \${FOAMDEM_PYTHON:-python3} meshConvergence.py --d-over-h 0.5 --with-only --kernel cell --set checkMomentumBalance true --work runsCell --out cell.dat && \${FOAMDEM_PYTHON:-python3} meshConvergence.py --d-over-h 0.5 --with-only --set checkMomentumBalance true --work runsSmoothed --out smoothed.dat && ${BALANCE} runsCell/0.5_with/log.pisoDEMFoam 1e-10 && ${BALANCE} runsSmoothed/0.5_with/log.pisoDEMFoam 1e-10")
set_tests_properties(momentumBalance.undisturbedVelocity PROPERTIES
    LABELS integration TIMEOUT 300)
