# denseRCP with the divided void fraction: besides boundedness and
# conservation, the bed settles (no particle rises, the fluid is no faster
# than the fastest particle)
VOIDFRACTION=divided
. "$(dirname "${BASH_SOURCE[0]}")/denseRCP.sh"
CHECK+=(--physics settle)
