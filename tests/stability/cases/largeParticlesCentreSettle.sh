# largeParticlesOverride (centre void fraction, run despite the guard's
# refusal) with the settling check of largeParticlesSmoothed (NOT
# registered: fails, the 8 mm sphere rises and the fluid runs at 1.3 m/s;
# see README.md)
. "$(dirname "${BASH_SOURCE[0]}")/largeParticlesOverride.sh"
CHECK+=(--physics settle)
