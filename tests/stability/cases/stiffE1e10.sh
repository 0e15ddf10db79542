# Stiff contacts, E = 1e10 Pa (DEM step 2.5e-7 s = 9 % of the Rayleigh
# time; LIGGGHTS needs 'hard_particles yes' above 1e9 Pa): the block of
# stiffE1e9 hits the floor at 0.5 m/s
. "$here/stiffBlock.inc"
setup()
{
    sed -i 's/^soft_particles .*/hard_particles  yes/' DEM/in.liggghts
    stiffBlock 1e10 2.5e-7 400
}
LIMIT=90
CHECK=(--particles 48 --physics stiff)
