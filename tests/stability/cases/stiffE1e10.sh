# Stiff contacts, E = 1e10 Pa (DEM step 2.5e-7 s = 9 % of the Rayleigh
# time; LIGGGHTS needs 'hard_particles yes' above 1e9 Pa): the block of
# stiffE1e9 hits the floor at 0.5 m/s
setup()
{
    mesh 24 24 24 3 3 3
    sed -i 's/^soft_particles .*/hard_particles  yes/' DEM/in.liggghts
    param E 1e10
    param v0 0.5
    param column 3
    param dp 0.002
    param rhop 2500
    timing 2.5e-7 400 0.02 40
    { atoms 4 4 3 0.0022 0.0087 0.0087 0.0011
      echo "set             type 1 diameter \${dp} density \${rhop}"
      echo "velocity        all set 0 0 -\${v0} units box"; } > DEM/particles
    cat > DEM/extra <<'END'
# Every DEM step: largest floor overlap, largest pair overlap, KE + PE
compute         contacts all pair/gran/local delta
compute         pairOverlap all reduce max c_contacts[1]
compute         kinetic all ke
variable        wallOverlap equal ${dp}/2-bound(all,zmin)
variable        pairOverlap equal c_pairOverlap
variable        energy equal c_kinetic+mass(all)*${g}*xcm(all,z)
fix             stiff all print 1 "${t} ${wallOverlap} ${pairOverlap} ${energy}" file DEM/post/stiff.dat screen no title "# t wallOverlap pairOverlap KE+PE"
END
}
LIMIT=90
CHECK=(--particles 48 --physics stiff)
