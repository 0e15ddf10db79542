# settlingSphere tests (FOAMDEM_WORK and TUT come from integration.cmake)

# settlingSphere: terminal velocity within 0.5 % of the ODE, per drag law
foreach(law schillerNaumann diFelice)
    add_test(NAME settlingSphere.${law}
        COMMAND ${TUT} settlingSphere ${FOAMDEM_WORK}/settlingSphere_${law}
                -ci -drag ${law})
    set_tests_properties(settlingSphere.${law} PROPERTIES
        LABELS "integration;tutorial" TIMEOUT 300
        FIXTURES_SETUP settling_${law})
endforeach()

# Particles written as a lagrangian cloud that foamToVTK exports
add_test(NAME particleOutput.foamToVTK
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkParticleVTK
            ${FOAMDEM_WORK}/settlingSphere_schillerNaumann 1)
set_tests_properties(particleOutput.foamToVTK PROPERTIES
    LABELS integration TIMEOUT 120 FIXTURES_REQUIRED settling_schillerNaumann)

# Demand-driven exchange: a drag-only scene pulls no spin or orientation
add_test(NAME exchangePlan.dragOnly
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkExchangePlan
            ${FOAMDEM_WORK}/settlingSphere_schillerNaumann/log.pisoDEMFoam
            "position velocity radius id implicitCoeff fluidVelocity explicitForce"
            "angularVelocity orientation density torque")
set_tests_properties(exchangePlan.dragOnly PROPERTIES
    LABELS integration TIMEOUT 30 FIXTURES_REQUIRED settling_schillerNaumann)
