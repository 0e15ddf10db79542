# Particles larger than cells with the centre void fraction: spheres of
# 8 mm and 6 mm (2 and 1.5 cell sizes) on 4 mm cells. The stability guard
# refuses (centre puts a particle's whole volume into one cell, which
# cannot hold it), naming couplingProperties, the keyword voidFraction, the
# models that can (divided, smoothed) and the override
. "$here/largeParticles.inc"
setup() { largeParticles; }
run_case()
{
    expectFailure 10 "stability guard refuses this case: +- particles up to 2 cell sizes across .*'voidFraction centre;' in constant/couplingProperties.*keyword voidFraction .*'divided'.*'smoothed'.*stabilityGuard \{ override true; \} in constant/couplingProperties"
}
