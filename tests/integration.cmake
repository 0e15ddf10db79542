# Integration tests: tutorials' CI modes, particle output, bad input.
set(FOAMDEM_WORK ${CMAKE_BINARY_DIR}/work)
# Created at configure time: some tests copy a case into it with a plain cp
file(MAKE_DIRECTORY ${FOAMDEM_WORK})
set(TUT ${CMAKE_CURRENT_SOURCE_DIR}/integration/runTutorial)

# Each tutorial registers its tests in tests/tutorials/<name>.cmake, each
# OpenFOAM-side test application in tests/foamApps/<name>.cmake, the Python
# post-processing's unit tests in tests/python/<name>.cmake
file(GLOB TUTORIAL_TESTS
    ${CMAKE_CURRENT_SOURCE_DIR}/tutorials/*.cmake
    ${CMAKE_CURRENT_SOURCE_DIR}/foamApps/*.cmake
    ${CMAKE_CURRENT_SOURCE_DIR}/python/*.cmake)
foreach(t ${TUTORIAL_TESTS})
    include(${t})
endforeach()

# Bad input: each case must fail fast with a clear message
execute_process(
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/badInput/runBadInput --list
    OUTPUT_VARIABLE BAD_CASES OUTPUT_STRIP_TRAILING_WHITESPACE)
string(REPLACE "\n" ";" BAD_CASES "${BAD_CASES}")
foreach(bad ${BAD_CASES})
    add_test(NAME badInput.${bad}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/badInput/runBadInput ${bad}
                ${FOAMDEM_WORK}/badInput/${bad})
    if(bad MATCHES "Parallel$")
        # np[...] = 2 in runBadInput
        set_tests_properties(badInput.${bad} PROPERTIES
            LABELS "badInput;parallel" TIMEOUT 60 PROCESSORS 2)
    else()
        set_tests_properties(badInput.${bad} PROPERTIES LABELS badInput TIMEOUT 60)
    endif()
endforeach()

# The tutorials' Allrun on bad command lines (no solver runs): an
# option without its value ('-end -continue' must not start a new run), an
# unknown option, -np 0, -end at the start (spoutedBed: past its schedule)
# or not a number, a new run on a case that has run, and -continue on
# another number of processes or variant (-ci) than the run's or past the
# case's end stop with a message naming the option, the run's outputs or
# what to give instead, and leave the case's files as they were
# (checkAllrunRefusals). Seen failing with the Allrun and prepare.py of
# spoutedBed from before these checks (17 failures: -lift on over a run
# started a new fill and deleted its 100 Hz history), and with those of
# a2a8a0b (1, 10 and 18 failures: a -continue on 1 of 2 processors went on
# to the solver; cohesiveBedEvacuation's changed setupDict first)
# The six short tutorials: an option without its value, an unknown option
# and a new run on a case that has run (seen failing with a2a8a0b's
# settlingSphere Allrun, 4 failures: it set -ci's endTime in controlDict and
# went on to the run, whose steps runApplication then skipped as run)
# -continue when the latest write has no DEM restart (the six short
# tutorials and cohesiveBedEvacuation): refused before anything is written,
# naming the write and how to remove it (seen failing with bd716ad's
# scripts: settlingSphere's -ci -continue wrote controlDict first, and no
# message named the write)
# spoutedBed's -ci -continue on a full run (its particle table's header):
# refused (seen failing with prepare.py's variant check left out: the
# set-up was rewritten for the CI bed)
foreach(tut spoutedBed densePneumaticConveying cohesiveBedEvacuation
        ErgunPackedBed fluidizedBed liquidFluidizedBed mixedBedNonSpherical
        settlingNonSpherical settlingSphere)
    add_test(NAME badInput.allrun.${tut}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkAllrunRefusals ${tut}
                ${FOAMDEM_WORK}/badInput/allrun_${tut})
    set_tests_properties(badInput.allrun.${tut} PROPERTIES LABELS badInput TIMEOUT 600)
endforeach()

# ./Allclean puts back the files an Allrun option edited (-ci, -drag, -dt,
# -ddt, -np, startFrom, -lift's forceModels: foamDEMEdit,
# foamDEMRestoreOriginals) and keeps a file changed by hand since
# (checkAllcleanRestores: settlingSphere and ErgunPackedBed CI runs, a
# continuation, three changes by hand, the other Allcleans). Seen
# failing with the scripts of 202ab58 (Allclean left 2 and 4 edited files:
# a later ./Allrun ran with the earlier -drag and -ci endTime), with
# foamDEMContinue's startFrom set by plain sed, with foamDEMEdit taking
# over a change by hand, with fluidizedBed's Allclean not restoring, and
# with the Allcleans of bd716ad (3 failures: densePneumaticConveying's and
# spoutedBed's left the .orig of their -np and -lift edits; spoutedBed's
# reset a change by hand of forceModels, keeping no .tutorial)
add_test(NAME tutorials.allcleanRestores
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkAllcleanRestores
            ${FOAMDEM_WORK}/allcleanRestores)
set_tests_properties(tutorials.allcleanRestores PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 600)

# Every edit an Allrun makes to a tutorial's own file (system/, constant/,
# DEM/ but DEM/post/) goes through foamDEMEdit, so that Allclean can put
# it back (checkAllrunEdits, a static check of the nine Allrun: 20 edits
# found). Seen failing with the Allrun of bd716ad (5 bare edits in
# spoutedBed, densePneumaticConveying and cohesiveBedEvacuation)
add_test(NAME tutorials.allrunEdits
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkAllrunEdits)
set_tests_properties(tutorials.allrunEdits PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 60)

# Every coupled run in an Allrun is followed by 'foamDEMStoppedEarly &&
# exit 0' before its post-processing, so that a run stopped by SIGUSR2
# (stopSignals.H) ends the Allrun unprocessed, status 0
# (checkAllrunStops, static: 25 coupled runs in the nine Allrun). Seen
# failing with the Allrun of 0209a0d (all 25)
add_test(NAME tutorials.allrunStops
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkAllrunStops)
set_tests_properties(tutorials.allrunStops PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 60)

# doc/cluster.md's SLURM batch script under a stand-in for SLURM
# (checkJobScript): job 1 (settlingSphere, np 2), its ranks frozen once
# they have blocked the signals, gets SIGUSR2 as --signal=B:USR2 sends
# it, passes it to its pisoDEMFoam (foamDEMSignalRun), exits 0
# unprocessed and submits job.slurm once; job 2 continues to the end,
# post-processes ('pass yes') and submits nothing. Seen failing with the
# solver's stopSignals.check() taken out (job 1 ran to its end), and,
# with OpenFOAM's own signal handlers instead, with a late SIGUSR2
# crashing rank 1 in MPI_Finalize.
add_test(NAME cluster.jobScript
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkJobScript
            ${FOAMDEM_WORK}/jobScript)
set_tests_properties(cluster.jobScript PROPERTIES
    LABELS "integration;tutorial;parallel" TIMEOUT 600 PROCESSORS 2)

# etc/RunFunctions' foamDEMSetEntry on a scratch dictionary: sets a
# top-level 'KEY VALUE;' line's value only (a trailing comment holding a
# ';' kept; a longer key and the key in a sub-dictionary left alone; sed's
# special characters and a leading '-' written as given), and refuses a key
# with no line or no value, a value holding a ';' and a line whose value
# it cannot match. Seen failing with the setter of 2ae5696 (its greedy
# '.*;' ate the comment up to its last ';') and with that of 163e1b2 (a
# ';' value written, the unmatched line taken as set from its comment)
add_test(NAME tutorials.runFunctions.setEntry
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/integration/checkSetEntry
            ${FOAMDEM_WORK}/setEntry)
set_tests_properties(tutorials.runFunctions.setEntry PROPERTIES
    LABELS "integration;tutorial" TIMEOUT 60)

# Bad input in a DEM-only stage (foamDEMLiggghts, the tutorials' packing):
# the LIGGGHTS error and the failing command on stderr and in the log,
# non-zero exit, every rank stopped
execute_process(
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/badInput/runBadPacking --list
    OUTPUT_VARIABLE BAD_PACKING OUTPUT_STRIP_TRAILING_WHITESPACE)
string(REPLACE "\n" ";" BAD_PACKING "${BAD_PACKING}")
foreach(bad ${BAD_PACKING})
    add_test(NAME badInput.packing.${bad}
        COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/badInput/runBadPacking ${bad}
                ${FOAMDEM_WORK}/badInput/packing_${bad})
    if(bad MATCHES "Parallel$")
        set_tests_properties(badInput.packing.${bad} PROPERTIES
            LABELS "badInput;parallel" TIMEOUT 60 PROCESSORS 2)
    else()
        set_tests_properties(badInput.packing.${bad} PROPERTIES
            LABELS badInput TIMEOUT 60)
    endif()
endforeach()
