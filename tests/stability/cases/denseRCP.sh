# Dense packing near random close packing: 244 glass spheres (3.38 mm) on a
# body-centred cubic lattice (a = 4 mm) at solid fraction 0.63, each moved
# by up to 0.02 mm, in water with the Gidaspow (Ergun) drag; the bed
# settles into contact under gravity. Centre void fraction; many centres
# start on cell faces (lattice planes at 8 and 16 mm)
setup()
{
    mesh 24 24 40 3 3 5
    fd $cp -entry voidFraction -set ${VOIDFRACTION:-centre}
    fd $cp -entry forceModels -set "(gidaspow archimedes pressureGradient)"
    param dp 0.0033771
    param rhop 2500
    timing 4e-5 25 0.1 20
    { atoms 6 6 4 0.004 0.002 0.002 0.002 0.00002
      atoms 5 5 4 0.004 0.004 0.004 0.004 0.00002
      echo "set             type 1 diameter \${dp} density \${rhop}"; } > DEM/particles
}
# --dense: the precondition that the case is dense. The densest cell's
# solid fraction, minimum over the writes: 0.551 with the linear pressure
# scheme, 0.512 with the conductance scheme (the bed's edge cells get their
# full drag, so the settling bed's lower cells loosen slightly)
CHECK=(--particles 244 --dense 0.5)
