"""Single-particle drag laws, written independently of the C++ kernels so
that the validation cases check the C++ against a second implementation.
Each returns K = |F|/|w| [kg/s] for one particle, model A convention."""
import math


def schiller_naumann(d, rho, mu, eps, slip):
    re = rho * slip * d / mu
    if re <= 0:
        return 3 * math.pi * mu * d
    cd = 24 / re * (1 + 0.15 * re ** 0.687) if re <= 1000 else 0.44
    return math.pi / 8 * cd * rho * d * d * slip


def di_felice(d, rho, mu, eps, slip):
    re = eps * rho * slip * d / mu
    if re <= 0:
        return math.pi / 8 * 4.8 ** 2 * mu * d * eps ** (1 - 3.7)
    cd = (0.63 + 4.8 / math.sqrt(re)) ** 2
    chi = 3.7 - 0.65 * math.exp(-(1.5 - math.log10(re)) ** 2 / 2)
    return math.pi / 8 * cd * rho * d * d * slip * eps ** (2 - chi)


LAWS = {
    "schillerNaumann": schiller_naumann,
    "diFelice": di_felice,
}


def terminal_velocity(law, d, rho, mu, eps, net_weight):
    """Solve K(v) v = net_weight by bisection."""
    lo, hi = 0.0, 1.0
    while law(d, rho, mu, eps, hi) * hi < net_weight:
        hi *= 2
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if law(d, rho, mu, eps, mid) * mid < net_weight:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def settle(law, d, rho, mu, eps, rhop, g, t_end, dt=1e-5):
    """Velocity history of a sphere released from rest, m dv/dt =
    (rhop - rho) V g - K(v) v, by classical RK4. Returns (t, v) lists."""
    vol = math.pi * d ** 3 / 6
    m = rhop * vol
    w = (rhop - rho) * vol * g

    def acc(v):
        return (w - law(d, rho, mu, eps, abs(v)) * v) / m

    t, v = 0.0, 0.0
    ts, vs = [t], [v]
    n = int(round(t_end / dt))
    for _ in range(n):
        k1 = acc(v)
        k2 = acc(v + 0.5 * dt * k1)
        k3 = acc(v + 0.5 * dt * k2)
        k4 = acc(v + dt * k3)
        v += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        t += dt
        ts.append(t)
        vs.append(v)
    return ts, vs
