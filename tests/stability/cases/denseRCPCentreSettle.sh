# denseRCP (centre void fraction) with the settling check of
# denseRCPDivided (NOT registered: fails, particles are thrown up by 20 mm
# at 1.1 m/s; see README.md)
. "$(dirname "${BASH_SOURCE[0]}")/denseRCP.sh"
CHECK+=(--physics settle)
