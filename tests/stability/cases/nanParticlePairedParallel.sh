# failureDEMRestart lastGoodStep on 2 ranks (CFD and DEM split at x = 20 mm,
# one sphere on each): the DEM force is NaN at step 2000 on both, the stop
# writes each rank's fluid fields of 0.019 s, the master moves the DEM
# restart of that step to DEM/restart/0.019.restart while the other rank
# waits, and all ranks end non-zero. LIGGGHTS reads the restart at step
# 1900 with both spheres at the velocities of the DEM's dump at 1900.
NAN_STEP=2000
. "$here/cases/nanParticlePaired.sh"
eval "pairedSetup() $(declare -f setup | sed 1d)"
setup()
{
    pairedSetup
    sed -i 's/^boundary        f f f$/&\nprocessors      2 1 1/' DEM/in.liggghts
    cat > DEM/particles <<'END'
# One glass sphere on each rank, 1 mm, released from rest
create_atoms    1 single 0.01 0.02 0.06 units box
create_atoms    1 single 0.03 0.02 0.06 units box
set             type 1 diameter 0.001 density 2500
END
}
run_case()
{
    decomposePar -force > log.decomposePar 2>&1 || { echo "FAIL: decomposePar"; return 1; }
    SOLVER="mpirun -np 2 pisoDEMFoam -parallel" expectFailure 60 \
        "NaN/Inf at t = 0.02 s: particle id [12] in cell [0-9]+ of rank [01]: velocity is not finite.*written to time 0.019, the DEM state of that step to [^ ]*DEM/restart/0.019.restart;" \
        "" "DEM/restart/0.019.restart" "DEM/restart/0.019.step" \
        "processor0/0.019/U" "processor1/0.019/U" \
        && "$PY" "$here/checkPairedRestart.py" . 0.019 1900
}
