"""Single-particle drag laws, written independently of the C++ kernels so
that the tutorials' checks verify the C++ against a second implementation
(verification, not validation: both follow the same published formula).
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


def _re(d, rho, mu, eps, slip):
    return eps * rho * slip * d / mu


def koch_hill(d, rho, mu, eps, slip):
    """Hill, Koch & Ladd (2001), blend of Benyahia et al. (2006):
    K = V_p beta/phi = 3 pi mu d eps^2 (F0 + F3 Re/2)."""
    phi = 1 - eps
    re = _re(d, rho, mu, eps, slip)
    if phi < 0.4:
        plogp = phi * math.log(phi) if phi > 0 else 0.0
        f0 = ((1 + 3 * math.sqrt(phi / 2) + 135 / 64 * plogp + 16.14 * phi)
              / (1 + 0.681 * phi - 8.48 * phi ** 2 + 8.16 * phi ** 3))
    else:
        f0 = 10 * phi / eps ** 3
    f3 = 0.0673 + 0.212 * phi + 0.0232 / eps ** 5
    return 3 * math.pi * mu * d * eps ** 2 * (f0 + 0.5 * f3 * re)


def gidaspow(d, rho, mu, eps, slip):
    """Ergun for eps <= 0.8, Wen-Yu above; K = V_p beta/phi."""
    phi = 1 - eps
    vp = math.pi * d ** 3 / 6
    if eps <= 0.8:
        return vp * (150 * phi * mu / (eps * d * d) + 1.75 * rho * slip / d)
    re = _re(d, rho, mu, eps, slip)
    if re <= 0:
        return vp * 0.75 * 24 * mu / (d * d) * eps ** -2.65
    cd = 24 / re * (1 + 0.15 * re ** 0.687) if re <= 1000 else 0.44
    return vp * 0.75 * cd * eps * rho * slip * eps ** -2.65 / d


def beetstra(d, rho, mu, eps, slip):
    """Beetstra, van der Hoef & Kuipers (2007): K = 3 pi mu d eps F_B."""
    phi = 1 - eps
    re = _re(d, rho, mu, eps, slip)
    fb = 10 * phi / eps ** 2 + eps ** 2 * (1 + 1.5 * math.sqrt(phi))
    if re > 0:
        fb += (0.413 * re / (24 * eps ** 2)
               * (1 / eps + 3 * eps * phi + 8.4 * re ** -0.343)
               / (1 + 10 ** (3 * phi) * re ** (-(1 + 4 * phi) / 2)))
    return 3 * math.pi * mu * d * eps * fb


def tenneti(d, rho, mu, eps, slip):
    """Tenneti, Garg & Subramaniam (2011): F is the total force (mean
    pressure gradient included), the model-A drag (1 - phi) F:
    K = 3 pi mu d eps^2 F."""
    phi = 1 - eps
    re = _re(d, rho, mu, eps, slip)
    f = ((1 + 0.15 * re ** 0.687) / eps ** 3 + 5.81 * phi / eps ** 3
         + 0.48 * phi ** (1 / 3) / eps ** 4
         + phi ** 3 * re * (0.95 + 0.61 * phi ** 3 / eps ** 2))
    return 3 * math.pi * mu * d * eps ** 2 * f


def rong(d, rho, mu, eps, slip):
    """Rong, Dong & Yu (2013): Di Felice's form with their chi(eps, Re)."""
    re = _re(d, rho, mu, eps, slip)
    if re <= 0:
        chi = 2.65 * (eps + 1)
        return math.pi / 8 * 4.8 ** 2 * mu * d * eps ** (1 - chi)
    chi = (2.65 * (eps + 1) - (5.3 - 3.5 * eps) * eps ** 2
           * math.exp(-(1.5 - math.log10(re)) ** 2 / 2))
    cd = (0.63 + 4.8 / math.sqrt(re)) ** 2
    return math.pi / 8 * cd * rho * d * d * slip * eps ** (2 - chi)


def hoelzer_sommerfeld(d, rho, mu, eps, slip):
    """Hoelzer & Sommerfeld (2008) for a sphere (Phi = Phi_perp = Phi_par
    = 1), C_D = 24/Re + 3/sqrt(Re) + 0.42, with Di Felice's voidage
    function (the model's default): K = (pi/8) C_D rho d^2 slip eps^(2-chi).
    Free spheres only: the shapes of bodies are not handled here."""
    re = max(_re(d, rho, mu, eps, slip), 1e-12)
    slip = re * mu / (eps * rho * d)
    cd = 24 / re + 3 / math.sqrt(re) + 0.42
    chi = 3.7 - 0.65 * math.exp(-(1.5 - math.log10(re)) ** 2 / 2)
    return math.pi / 8 * cd * rho * d * d * slip * eps ** (2 - chi)


LAWS = {
    "schillerNaumann": schiller_naumann,
    "diFelice": di_felice,
    "kochHill": koch_hill,
    "gidaspow": gidaspow,
    "beetstra": beetstra,
    "tenneti": tenneti,
    "rong": rong,
    "hoelzerSommerfeld": hoelzer_sommerfeld,
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
