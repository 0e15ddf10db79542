# An error on one rank stops all ranks: a parallel run (2 ranks, CFD and
# DEM both split at x = 20 mm) where only rank 1 meets a LIGGGHTS error.
# A block of 45 spheres on rank 1 falls onto the floor; the DEM allows at
# most 2 neighbours per particle ('neigh_modify one 2'), which holds while
# the layers fall apart and overflows on rank 1 once they land
# (LIGGGHTS error->one). The single sphere on rank 0 never errs (case
# oneRankErrorMaster: the same with the roles of the ranks swapped). The run
# must end non-zero within 20 s with LIGGGHTS's message, without hanging.
setup()
{
    timing 1e-5 100 0.1 20
    sed -i 's/^boundary        f f f$/&\nprocessors      2 1 1/' DEM/in.liggghts
    sed -i 's/^neigh_modify    delay 0$/neigh_modify    delay 0 one 2 page 1000/' DEM/in.liggghts
    { for k in 0 1 2 3 4; do for j in 0 1 2; do for i in 0 1 2; do
          awk -v i=$i -v j=$j -v k=$k 'BEGIN { printf "create_atoms    1 single %g %g %g units box\n",
              '${CLUSTER_X:-0.028}' + 0.0013*i, 0.018 + 0.0013*j, 0.0006 + 0.003*k }'
      done; done; done
      echo "create_atoms    1 single ${SINGLE_X:-0.01} 0.02 0.01 units box"
      echo "set             type 1 diameter 0.001 density 2500"; } > DEM/particles
}
run_case()
{
    decomposePar -force > log.decomposePar 2>&1 || { echo "FAIL: decomposePar"; return 1; }
    SOLVER="mpirun -np 2 pisoDEMFoam -parallel" expectFailure 20 \
        "ERROR on proc ${ERROR_RANK:-1}: Neighbor list overflow"
    local status=$?
    # It happened mid-run, not at start-up
    local t
    t=$(grep '^Time = ' log.pisoDEMFoam | tail -1)
    echo "last CFD step started: ${t:-none}"
    [ -n "$t" ] || { echo "FAIL: the error came before the first step"; status=1; }
    return $status
}
