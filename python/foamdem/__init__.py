"""foamDEM post-processing helpers (numpy/matplotlib from Debian)."""
