# Zero particles: the coupling runs with an empty DEM; eps = 1, U stays 0
# (LIGGGHTS cannot size its atom-sorting bins without particles or an
# insertion fix: 'atom_modify sort 0 0.0' switches sorting off)
setup()
{
    echo "# no particles" > DEM/particles
    sed -i 's/^atom_modify     map array$/&\natom_modify     sort 0 0.0/' DEM/in.liggghts
    timing 1e-5 100 0.02 10
}
CHECK=(--particles 0 --u-max 1e-12 --expect "no particles at start")
