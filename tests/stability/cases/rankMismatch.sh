# Bad input, parallel: a decomposition that does not match the rank count.
# (a) decomposeParDict and the processor directories say 3, the run has 2
# ranks; (b) decomposeParDict says 2 but 3 processor directories exist.
# Each run must stop non-zero within 10 s with OpenFOAM's message, no hang.
setup()
{
    timing 1e-5 100 0.02 10
    fd system/decomposeParDict -entry numberOfSubdomains -set 3
    fd system/decomposeParDict -entry coeffs.n -set "(1 1 3)"
}
run_case()
{
    local status=0
    decomposePar -force > log.decomposePar 2>&1 || { echo "FAIL: decomposePar"; return 1; }
    echo "processor directories: $(ls -d processor* | tr '\n' ' ')"
    echo "-- (a) decomposeParDict: 3 subdomains, mpirun -np 2"
    SOLVER="mpirun -np 2 pisoDEMFoam -parallel" expectFailure 10 \
        "decomposeParDict\" specifies 3 processors but job was started with 2 processors" \
        || status=1
    echo "-- (b) decomposeParDict: 2 subdomains, 3 processor directories, mpirun -np 2"
    fd system/decomposeParDict -entry numberOfSubdomains -set 2
    # OpenFOAM counts the directories only in some set-ups; otherwise the
    # mesh's processor patches fail
    SOLVER="mpirun -np 2 pisoDEMFoam -parallel" expectFailure 10 \
        "number of processor directories = 3 is not equal to the number of processors = 2|out of range neighbour processor 2.*incorrect number of processors" \
        || status=1
    return $status
}
