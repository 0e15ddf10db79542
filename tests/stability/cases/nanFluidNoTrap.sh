# nanFluid with OpenFOAM's floating-point trapping off (FOAM_SIGFPE=false)
# (NOT registered: shows what follows once the SIGFPE trap no longer
# ends the run first; see README.md)
export FOAM_SIGFPE=false
. "$(dirname "${BASH_SOURCE[0]}")/nanFluid.sh"
