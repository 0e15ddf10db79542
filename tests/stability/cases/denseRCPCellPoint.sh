# denseRCP (divided void fraction) with couplingKernel cellPoint: u_f and eps
# interpolated at the particles, and with implicit coupling the fluid's
# explicit share -K_p (u_f - U_c) in a dense bed of large K_p; besides
# boundedness and conservation (momentum balance <= 1e-10), the bed settles
VOIDFRACTION=divided
. "$(dirname "${BASH_SOURCE[0]}")/denseRCP.sh"
eval "denseSetup() $(declare -f setup | sed 1d)"
setup() { denseSetup && fd $cp -entry couplingKernel -add cellPoint; }
CHECK+=(--physics settle)
