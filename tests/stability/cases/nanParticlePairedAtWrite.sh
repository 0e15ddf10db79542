# failureDEMRestart lastGoodStep, a stop right after a write time: the DEM
# force is NaN at step 2100 only (the coupling step ending at 0.021 s), so
# the last good step, 0.02 s, is a write time, whose own DEM restart
# (DEM/restart/0.02.restart) stands for it: the message names it, and
# LIGGGHTS reads it at step 2000 with the dump's velocities at 2000.
setup()
{
    timing 1e-5 100 0.05 10
    cat > DEM/extra <<'END'
# (-1)^0.5 is NaN: only at step 2100
variable        fnan equal (2*(step!=2100)-1)^0.5-1
fix             nan all addforce 0 0 v_fnan
END
    fd $cp -entry failureDEMRestart -add lastGoodStep
}
run_case()
{
    expectFailure 60 \
        "NaN/Inf at t = 0.021 s: particle id 1 in cell [0-9]+ of rank 0: velocity is not finite.*written to time 0.02, the DEM state of that step to [^ ]*DEM/restart/0.02.restart;" \
        0.02 "DEM/restart/0.02.restart" "DEM/post/restart.atFailure_0.021" \
        && "$PY" "$here/checkFailureParticles.py" . 0.02 2000 2100 \
        && "$PY" "$here/checkPairedRestart.py" . 0.02 2000
}
