# NaN at run time with failureDEMRestart lastGoodStep: as nanParticle (a
# DEM force NaN only at step 2000, the coupling step ending at 0.02 s), and
# the stop leaves the DEM restart of the last good step where a write
# time's goes, DEM/restart/0.019.restart, beside the fluid fields and the
# particles of 0.019 s. LIGGGHTS reads that restart at step 1900 with the
# velocities of the DEM's own dump at step 1900 (checkPairedRestart.py).
# The other nanParticlePaired* cases set NAN_STEP, FAIL_T, GOOD_T and
# GOOD_STEP and source this file.
: "${NAN_STEP:=2000}" "${FAIL_T:=0.02}" "${GOOD_T:=0.019}" "${GOOD_STEP:=1900}"
setup()
{
    timing 1e-5 100 0.05 10
    nanAtStep "$NAN_STEP"
    fd $cp -entry failureDEMRestart -add lastGoodStep
}
run_case()
{
    expectFailure 60 \
        "NaN/Inf at t = $FAIL_T s: particle id 1 in cell [0-9]+ of rank 0: velocity is not finite.*written to time $GOOD_T, the DEM state of that step to [^ ]*DEM/restart/$GOOD_T.restart;" \
        "$GOOD_T" "DEM/restart/$GOOD_T.restart" "DEM/restart/$GOOD_T.step" \
        "DEM/post/restart.atFailure_$FAIL_T" \
        && "$PY" "$here/checkFailureParticles.py" . "$GOOD_T" "$GOOD_STEP" "$NAN_STEP" \
        && "$PY" "$here/checkPairedRestart.py" . "$GOOD_T" "$GOOD_STEP"
}
