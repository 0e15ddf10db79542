# NaN at run time, particle side: a DEM force that is NaN at step 2000 only
# (the last DEM step of the coupling step ending at t = 0.02 s) makes the
# sphere's velocity NaN while its position is still finite. The solver must
# stop non-zero naming the particle id, its cell and 'velocity', write the
# fluid fields and the particles (cloud) of t = 0.019 s and a DEM restart,
# nothing NaN in 0.019, and the cloud's velocity that of the DEM's own dump
# at step 1900 (checkFailureParticles.py).
setup()
{
    timing 1e-5 100 0.05 10
    nanAtStep 2000
}
run_case()
{
    expectFailure 60 \
        "NaN/Inf at t = 0.02 s: particle id 1 in cell [0-9]+ of rank 0: velocity is not finite" \
        0.019 "DEM/post/restart.atFailure_0.02" \
        && "$PY" "$here/checkFailureParticles.py" . 0.019 1900 2000
}
