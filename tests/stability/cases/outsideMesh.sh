# A particle outside the mesh: the DEM box is twice the CFD box in x; the
# particle at x = 60 mm falls freely while the one inside settles in water
setup()
{
    param xhi 0.08
    param idInside 1
    param idOutside 2
    cat > DEM/particles <<'END'
create_atoms    1 single 0.02 0.02 0.06 units box
create_atoms    1 single 0.06 0.02 0.06 units box
set             type 1 diameter 0.001 density 2500
END
    timing 1e-5 100 0.08 20
}
CHECK=(--particles 2 --outside 1 --physics outside --physics-tol 1e-9
       --expect "1 particle\(s\) not found in the CFD mesh at t = 0 s: they get no fluid force")
