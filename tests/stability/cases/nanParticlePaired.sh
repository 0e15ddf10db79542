# NaN at run time with failureDEMRestart lastGoodStep: as nanParticle (a
# DEM force NaN only at step 2000, the coupling step ending at 0.02 s), and
# the stop leaves the DEM restart of the last good step where a write
# time's goes, DEM/restart/0.019.restart, beside the fluid fields and the
# particles of 0.019 s. LIGGGHTS reads that restart at step 1900 with the
# velocities of the DEM's own dump at step 1900 (checkPairedRestart.py).
setup()
{
    timing 1e-5 100 0.05 10
    cat > DEM/extra <<'END'
# (-1)^0.5 is NaN: only at step 2000
variable        fnan equal (2*(step!=2000)-1)^0.5-1
fix             nan all addforce 0 0 v_fnan
END
    fd $cp -entry failureDEMRestart -add lastGoodStep
}
run_case()
{
    expectFailure 60 \
        "NaN/Inf at t = 0.02 s: particle id 1 in cell [0-9]+ of rank 0: velocity is not finite.*written to time 0.019, the DEM state of that step to [^ ]*DEM/restart/0.019.restart;" \
        0.019 "DEM/restart/0.019.restart" "DEM/restart/0.019.step" \
        "DEM/post/restart.atFailure_0.02" \
        && "$PY" "$here/checkFailureParticles.py" . 0.019 1900 2000 \
        && "$PY" "$here/checkPairedRestart.py" . 0.019 1900
}
