# highRe with the centre void fraction (NOT registered: fails by design,
# documents the face-crossing pressure pulse; see README.md)
VOIDFRACTION=centre
. "$(dirname "${BASH_SOURCE[0]}")/highRe.sh"
