# Integration tests: tutorials' CI modes, particle output, bad input.
set(FOAMDEM_WORK ${CMAKE_BINARY_DIR}/work)
set(TUT ${CMAKE_CURRENT_SOURCE_DIR}/integration/runTutorial)

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

# Bad input: each case must fail fast with a clear message
execute_process(
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/badInput/runBadInput --list
    OUTPUT_VARIABLE BAD_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
string(REPLACE "\n" ";" BAD_CASES "${BAD_CASES}")
foreach(bad ${BAD_CASES})
    add_test(NAME badInput.${bad}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/badInput/runBadInput ${bad}
                ${FOAMDEM_WORK}/badInput/${bad})
    set_tests_properties(badInput.${bad} PROPERTIES LABELS badInput TIMEOUT 60)
endforeach()
