# Unit tests of the Python post-processing (python/foamdem), run with the
# Debian interpreter that has numpy (FOAMDEM_PYTHON from etc/bashrc)

# The densePneumaticConveying reference's measures (slices, moving average,
# slug ends, front velocity, in-slug velocity, plane-crossing mass flow) on
# synthetic frames with answers from the definitions
add_test(NAME python.slugReferenceMeasures
    COMMAND sh -c "\"\${FOAMDEM_PYTHON:-python3}\" ${CMAKE_CURRENT_LIST_DIR}/testSlugReferenceMeasures.py")
set_tests_properties(python.slugReferenceMeasures PROPERTIES LABELS "unit;python" TIMEOUT 120)
