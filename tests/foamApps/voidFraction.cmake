# Void fraction models and particle averaging on real meshes
# (tests/foamApps/testVoidFraction; FOAMDEM_WORK comes from integration.cmake)
set(VF_RUN ${CMAKE_CURRENT_SOURCE_DIR}/foamApps/testVoidFraction/runTest)

# suite:mesh:processors
foreach(spec box:box:1 periodic:periodic:1 parallel:box:2 badInput:box:1 shapes:uniform:1)
    string(REPLACE ":" ";" spec ${spec})
    list(GET spec 0 suite)
    list(GET spec 1 mesh)
    list(GET spec 2 nProcs)
    add_test(NAME voidFraction.${suite}
        COMMAND ${VF_RUN} ${mesh} ${FOAMDEM_WORK}/voidFraction/${suite}
                ${suite} ${nProcs})
    set_tests_properties(voidFraction.${suite} PROPERTIES
        LABELS "unit;foam" TIMEOUT 120 PROCESSORS ${nProcs})
endforeach()
