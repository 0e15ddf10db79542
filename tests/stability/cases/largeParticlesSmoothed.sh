# largeParticles with the smoothed void fraction (divided base, smoothing
# length 1 particle diameter): the spheres settle and the fluid moves no
# faster than they do
VOIDFRACTION=smoothed
COEFFS="{ alphaMin 0.3; base divided; smoothingLengthInDiameters 1; }"
. "$here/largeParticles.inc"
setup() { largeParticles; }
CHECK=(--particles 2 --physics settle)
