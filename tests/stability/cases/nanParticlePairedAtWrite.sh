# failureDEMRestart lastGoodStep, a stop right after a write time: the DEM
# force is NaN at step 2100 only (the coupling step ending at 0.021 s), so
# the last good step, 0.02 s, is a write time, whose own DEM restart
# (DEM/restart/0.02.restart) stands for it: the message names it, and
# LIGGGHTS reads it at step 2000 with the dump's velocities at 2000.
NAN_STEP=2100 FAIL_T=0.021 GOOD_T=0.02 GOOD_STEP=2000
. "$here/cases/nanParticlePaired.sh"
