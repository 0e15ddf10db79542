# Particles leaving through an outlet in parallel, at a high rate (issue 14,
# the cohesive evacuation's outlet): the 'outlet' case (water in at the top
# at 5 cm/s, out at the bottom, no DEM wall at the outlet plane, boundary
# 'f': LIGGGHTS deletes what leaves the box) on 2 ranks, the CFD and the
# DEM both split at x = 12 mm, with a block of 10 x 10 x 8 spheres (1 mm,
# 2 mm apart) just above the outlet, half on each rank, and 12 more high up
# that stay. Hundreds of particles leave from both ranks during the run,
# many in the same coupling step: the coupling must go on with a particle
# count that changes every step, and the account must be exact (the
# outlet checks of checkStability.py on the reconstructed case).
. "$here/cases/outlet.sh"
eval "outlet_$(declare -f setup)"
setup()
{
    outlet_setup || return 1
    sed -i 's/^boundary        f f f$/&\nprocessors      2 1 1/' DEM/in.liggghts
    { atoms 10 10 8 0.002 0.003 0.003 0.0012
      for k in $(seq 0 11); do
          awk -v k=$k 'BEGIN { printf "create_atoms    1 single %g %g %g units box\n",
              0.006 + 0.004*(k%4), 0.012 + 0.004*((k%3) - 1), 0.05 + 0.001*k }'
      done
      echo "set             type 1 diameter \${dp} density \${rhop}"; } > DEM/particles
}
run_case()
{
    decomposePar -force > log.decomposePar 2>&1 || { echo "FAIL: decomposePar"; return 1; }
    local start status
    start=$(date +%s.%N)
    timeout ${LIMIT:-60} mpirun -np 2 pisoDEMFoam -parallel > log.pisoDEMFoam 2>&1
    status=$?
    echo "mpirun -np 2 pisoDEMFoam: exit $status after $(since $start) s"
    [ $status -eq 0 ] || { tail -20 log.pisoDEMFoam; return 1; }
    reconstructPar > log.reconstructPar 2>&1 || { echo "FAIL: reconstructPar"; return 1; }
    # Departures on both ranks: each rank's DEM count fell
    # The outlet checks and the suite's boundedness and conservation checks
    # on the reconstructed case (CHECK below)
    "$PY" "$here/checkStability.py" . "${CHECK[@]}"
}
CHECK=(--physics outlet --expect "particle\(s\) not found in the CFD mesh")
