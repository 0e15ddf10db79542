# largeParticles run anyway with 'stabilityGuard { override true; }': the
# guard reports the refusal and lets the case run; each sphere's own cell
# is clipped at alphaMin and the excess solid volume goes to the neighbours
. "$here/largeParticles.inc"
setup()
{
    largeParticles && fd $cp -entry stabilityGuard -set "{ override true; }"
}
CHECK=(--particles 2 --expect-clipped
       --expect "STABILITY GUARD OVERRIDDEN .*running despite 1 refusal\(s\):\s+\*\*\*\s+particles up to 2 cell sizes across")
