# NaN at run time, fluid side, with failureDEMRestart lastGoodStep: as
# nanFluid (the lid's velocity jumps to 1e300 m/s at 0.02 s), found after
# the coupling step of 0.02 s has written its DEM restart, so the stop must
# pair the fluid fields of 0.019 s with the other one, the DEM at step 1900,
# moved to DEM/restart/0.019.restart (checkPairedRestart.py).
. "$here/cases/nanFluid.sh"
eval "nanFluidSetup() $(declare -f setup | sed 1d)"
setup()
{
    nanFluidSetup && fd $cp -entry failureDEMRestart -add lastGoodStep
}
run_case()
{
    expectFailure 60 \
        "NaN/Inf in the fluid solution at t = 0.02 s: (U|p) in cell [0-9]+.*written to time 0.019, the DEM state of that step to [^ ]*DEM/restart/0.019.restart;" \
        0.019 "DEM/restart/0.019.restart" \
        && "$PY" "$here/checkFailureParticles.py" . 0.019 1900 2000 \
        && "$PY" "$here/checkPairedRestart.py" . 0.019 1900
}
