# oneRankError with the block on rank 0 (the master, whose LIGGGHTS screen
# output goes to log.liggghts) and the single sphere on rank 1
CLUSTER_X=0.008
SINGLE_X=0.03
ERROR_RANK=0
. "$(dirname "${BASH_SOURCE[0]}")/oneRankError.sh"
