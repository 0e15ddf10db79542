# failureDEMRestart lastGoodStep, a stop in the run's first coupling step
# (the DEM force NaN at step 100, t = 0.001 s): the last good step is the
# start, whose DEM state is the start itself, so the message says there is
# no DEM restart of it and none is left at DEM/restart/0.restart, from
# which a rerun from the start would continue.
NAN_STEP=100
. "$here/cases/nanParticlePaired.sh"
run_case()
{
    expectFailure 60 \
        "NaN/Inf at t = 0.001 s: particle id 1 in cell [0-9]+ of rank 0: velocity is not finite.*written to time 0 \(no DEM restart of that step: it was the run's start\);" \
        "" "DEM/post/restart.atFailure_0.001" || return 1
    if ls DEM/restart/0.restart DEM/restart/0.step 2> /dev/null
    then
        echo "FAIL: a DEM restart was left at the start time"; return 1
    fi
    echo "no DEM restart at the start time: ok"
}
