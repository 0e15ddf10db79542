# Particles leaving through an outlet: water enters at the top at 5 cm/s
# and leaves at the bottom; 12 glass spheres (1 mm) settle, those below
# ~30 mm leave the CFD mesh and the DEM box (non-periodic 'f' boundary:
# LIGGGHTS deletes them; 'thermo_modify lost ignore')
setup()
{
    mesh 24 24 64 3 3 8
    # walls on the sides, inlet on top, outlet at the bottom
    sed -i '/^boundary/,$d' system/blockMeshDict
    cat >> system/blockMeshDict <<'END'
boundary
(
    walls
    {
        type wall;
        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2));
    }
    inlet
    {
        type patch;
        faces ((4 5 6 7));
    }
    outlet
    {
        type patch;
        faces ((0 3 2 1));
    }
);
END
    sed -i '/^boundaryField/,$d' 0/U 0/p
    cat >> 0/U <<'END'
boundaryField
{
    walls  { type noSlip; }
    inlet  { type fixedValue; value uniform (0 0 -0.05); }
    outlet { type inletOutlet; inletValue uniform (0 0 0); value uniform (0 0 0); }
}
END
    cat >> 0/p <<'END'
boundaryField
{
    walls  { type zeroGradient; }
    inlet  { type zeroGradient; }
    outlet { type fixedValue; value uniform 0; }
}
END
    # No DEM wall at the outlet plane
    sed -i '/ zplane \${zlo}$/d' DEM/walls
    param dp 0.001
    param rhop 2500
    timing 1e-5 100 0.15 30
    { for k in $(seq 0 11); do
          awk -v k=$k 'BEGIN { printf "create_atoms    1 single %g %g %g units box\n",
              0.009 + 0.002*(k%4), 0.012 + 0.003*((k%3) - 1), 0.004 + 0.004*k }'
      done
      echo "set             type 1 diameter \${dp} density \${rhop}"; } > DEM/particles
}
CHECK=(--physics outlet --expect "particle\(s\) not found in the CFD mesh")
