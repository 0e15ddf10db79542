# fineImplicit with couplingKernel cellPoint: tau_p/dt = 1e-3, implicit
# coupling, and the explicit share -K_p (u_f - U_c) of the interpolated
# read; it must stay bounded and give the fine-particle physics
. "$(dirname "${BASH_SOURCE[0]}")/fineImplicit.sh"
eval "fineSetup() $(declare -f setup | sed 1d)"
setup() { fineSetup && fd $cp -entry couplingKernel -add cellPoint; }
