# densePneumaticConveying tests (FOAMDEM_WORK and TUT come from integration.cmake)

# CI variant: 0.2 m periodic pipe section (about 6300 particles): DEM-only
# packing of the slug, then 0.1 s coupled with the slug across the periodic
# plane. Fails unless no particle is lost, particles cross the periodic
# plane, every particle is located in a CFD cell at every step, the flow
# controller holds the 3 m/s mean gas velocity within 2 % after 0.02 s, and
# the reference's measures (slices, front velocity over +-3 frames of
# 0.005 s, plane-crossing mass flow) are all finite on its output.
add_test(NAME densePneumaticConveying.ci
    COMMAND ${TUT} densePneumaticConveying ${FOAMDEM_WORK}/densePneumaticConveying -ci)
set_tests_properties(densePneumaticConveying.ci PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 600
    FIXTURES_SETUP densePneumaticConveying_ci)

# Restart: the CI run continued from its last write (fields, controller state
# and DEM restart at 0.1 s) to 0.12 s, with the same checks over the joined
# segments
add_test(NAME densePneumaticConveying.continue
    COMMAND sh -c "cd ${FOAMDEM_WORK}/densePneumaticConveying && ./Allrun -ci -continue -end 0.12")
set_tests_properties(densePneumaticConveying.continue PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 300
    FIXTURES_REQUIRED densePneumaticConveying_ci)
