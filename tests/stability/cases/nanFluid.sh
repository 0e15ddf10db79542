# NaN at run time, fluid side: the lid's velocity (a uniformFixedValue
# table) jumps to 1e300 m/s at t = 0.02 s, so the fluid solution overflows.
# The solver must stop non-zero naming U or p and the cell, write the
# fluid fields and the particles (cloud) of t = 0.019 s, nothing NaN in
# 0.019, and the cloud's velocity that of the DEM's dump at step 1900, not
# of step 2000 (checkFailureParticles.py: the particles of the same step as
# the fluid fields, although the DEM had reached 0.02 s).
setup()
{
    timing 1e-5 100 0.05 10
    # A separate lid patch on top
    sed -i '/^boundary/,$d' system/blockMeshDict
    cat >> system/blockMeshDict <<'END'
boundary
(
    walls
    {
        type wall;
        faces ((0 3 2 1) (0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2));
    }
    lid
    {
        type wall;
        faces ((4 5 6 7));
    }
);
END
    sed -i '/^boundaryField/,$d' 0/U 0/p
    cat >> 0/U <<'END'
boundaryField
{
    walls { type noSlip; }
    lid
    {
        type            uniformFixedValue;
        uniformValue    table ((0 (0 0 0)) (0.0195 (0 0 0)) (0.02 (1e300 0 0)));
    }
}
END
    cat >> 0/p <<'END'
boundaryField
{
    walls { type zeroGradient; }
    lid   { type zeroGradient; }
}
END
}
run_case()
{
    expectFailure 60 \
        "NaN/Inf in the fluid solution at t = 0.02 s: (U|p) in cell [0-9]+" 0.019 \
        && "$PY" "$here/checkFailureParticles.py" . 0.019 1900 2000
}
