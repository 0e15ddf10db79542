"""The multisphere bodies' states the solver writes beside each DEM restart
(DEM/restart/<time>.bodies; src/foamDEM/demEngine/liggghts/multisphereBodies.H):
a three-line text header, then one row of 28 native doubles per body,
sorted by tag:

    foamDEMBodies 1
    step <N> bodies <n> columns 28
    tag type mass x y z vx vy vz q0 q1 q2 q3 exx exy exz eyx eyy eyz ezx ...
"""
import numpy as np


def read(path):
    """(step, column names, array of shape (bodies, columns))."""
    with open(path, "rb") as f:
        magic = f.readline().decode().strip()
        words = f.readline().decode().split()
        names = f.readline().decode().split()
        if magic != "foamDEMBodies 1" or len(words) != 6 or words[0::2] != [
                "step", "bodies", "columns"]:
            raise ValueError("%s is not a foamDEM body-state file (version 1)" % path)
        step, n, ncol = int(words[1]), int(words[3]), int(words[5])
        if len(names) != ncol:
            raise ValueError("%s: %d column names for %d columns" % (path, len(names), ncol))
        data = np.fromfile(f, dtype=np.float64)
    if data.size != n * ncol:
        raise ValueError("%s: %d numbers for %d bodies of %d columns (a cut-off file?)"
                         % (path, data.size, n, ncol))
    return step, names, data.reshape(n, ncol)


def counts_by_type(path):
    """{multisphere type: number of bodies} of a body-state file."""
    _, names, rows = read(path)
    types, counts = np.unique(rows[:, names.index("type")].astype(int), return_counts=True)
    return dict(zip(types.tolist(), counts.tolist()))
