# Particles larger than cells: spheres of 8 mm and 6 mm (2 and 1.5 cell
# sizes, rho 1100) settle in water on 4 mm cells with the centre void
# fraction; the guard warns, each sphere's own cell is clipped at alphaMin
# and the excess solid volume goes to the neighbours
setup()
{
    mesh 24 24 48 6 6 12
    fd $cp -entry voidFraction -set ${VOIDFRACTION:-centre}
    [ -n "${COEFFS:-}" ] && fd $cp -entry ${VOIDFRACTION}Coeffs -set "$COEFFS"
    param rhop 1100
    timing 1e-4 10 0.1 20
    cat > DEM/particles <<'END'
create_atoms    1 single 0.008 0.012 0.030 units box
create_atoms    1 single 0.017 0.012 0.036 units box
set             atom 1 diameter 0.008 density ${rhop}
set             atom 2 diameter 0.006 density ${rhop}
END
}
CHECK=(--particles 2 --expect-clipped --expect "particles up to 2 cell sizes across")
