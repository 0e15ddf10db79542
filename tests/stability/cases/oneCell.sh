# All particles in one cell: 64 glass spheres (2.25 mm) stacked 4 x 4 x 4,
# all centres in the bottom middle 8 mm cell; their volume is 0.75 of the
# cell's, above 1 - alphaMin = 0.7, so the cell is clipped and the excess
# goes to its neighbours
setup()
{
    mesh 24 24 24 3 3 3
    param dp 0.00225
    param rhop 2500
    timing 1e-5 100 0.05 10
    { atoms 4 4 4 0.00225 0.008625 0.008625 0.001125
      echo "set             type 1 diameter \${dp} density \${rhop}"; } > DEM/particles
}
CHECK=(--particles 64 --expect-clipped --physics oneCell)
