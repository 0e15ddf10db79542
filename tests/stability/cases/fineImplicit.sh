# Very fine particles: 1 mm glass in a liquid of mu = 138.9 Pa s, tau_p =
# 1e-6 s, CFD step 1e-3 s (tau_p/dt = 1e-3), DEM step 1e-4 s; implicit
# momentum coupling and implicit DEM drag integration
setup()
{
    fd constant/transportProperties -entry nu -set 0.1388888888888889
    param E 5e3
    param dp 0.001
    param rhop 2500
    timing 1e-4 10 0.05 10
    { for z in 0.036 0.06; do for y in 0.012 0.028; do for x in 0.012 0.028; do
          echo "create_atoms    1 single $x $y $z units box"
      done; done; done
      echo "set             type 1 diameter \${dp} density \${rhop}"; } > DEM/particles
}
CHECK=(--particles 8 --physics fine --physics-tol 0.001
       --expect "CFD step / tau_p = 1e\+03")
