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

# Restart: a copy of the CI run with its writes after 0.2 s removed,
# continued from the fields and the DEM restart at 0.2 s to the end
# (0.44 s); the checks pass on the joined segments (the probe files and
# the 100 Hz heights are joined, the later segment replacing the earlier)
add_test(NAME spoutedBed.continue
    COMMAND sh -c "rm -rf ${FOAMDEM_WORK}/spoutedBed_continue && cp -r ${FOAMDEM_WORK}/spoutedBed ${FOAMDEM_WORK}/spoutedBed_continue && cd ${FOAMDEM_WORK}/spoutedBed_continue && rm -rf 0.3 0.4 && ./Allrun -ci -continue")
set_tests_properties(spoutedBed.continue PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 900
    FIXTURES_REQUIRED spoutedBed_ci)
