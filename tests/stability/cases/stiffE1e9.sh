# Stiff contacts, E = 1e9 Pa (DEM step 1e-6 s = 12 % of the Rayleigh time):
# a 4 x 4 x 3 block of 2 mm glass spheres hits the floor at 0.5 m/s
. "$here/stiffBlock.inc"
setup()
{
    stiffBlock 1e9 1e-6 100
}
CHECK=(--particles 48 --physics stiff)
