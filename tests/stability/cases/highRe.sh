# Slip Reynolds number >= 1e4: a 10 mm glass sphere shot at 2 m/s along a
# 320 mm water channel (one 40 x 80 x 80 mm cell across) without gravity;
# Re falls from 2e4 to 1.1e4. Divided void fraction: with 'centre' the
# jump of eps as the sphere crosses a face gives a pressure pulse that
# kicks it by 5 % (case highReCentre, not registered: see README.md)
setup()
{
    mesh 320 80 80 8 1 1
    fd constant/g -entry value -set "(0 0 0)"
    fd $cp -entry voidFraction -set ${VOIDFRACTION:-divided}
    param g 0
    param dp 0.01
    param rhop 2500
    param v0 2
    timing 2e-5 10 0.03 50
    cat > DEM/particles <<'END'
create_atoms    1 single 0.02 0.04 0.04 units box
set             type 1 diameter ${dp} density ${rhop}
velocity        all set ${v0} 0 0 units box
END
    cat > DEM/extra <<'END'
variable        vx1 equal vx[1]
fix             history all print ${nout} "${t} ${vx1}" file DEM/post/history.dat screen no title "# t vx"
END
}
CHECK=(--particles 1 --physics highRe --physics-tol 0.02 --end-tol 0.005)
