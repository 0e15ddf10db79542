"""Analysis of the spouted bed's signals (tutorials/spoutedBed), as the
reference reported them (../shared/cases/spouted-bed.md): for each inlet
velocity plateau, the window without its first and last parts; in it the
gauge pressure's RMS deviation s = sqrt(sum (x_i - mean)^2/(N - 1)), its
amplitude spectrum (numpy's FFT) and dominant frequency, and the mean and
the maximum of the highest particle's height."""
import numpy as np


def window(t0, t1, skip_start, skip_end):
    """The analysed part of the plateau [t0, t1]."""
    return t0 + skip_start, t1 - skip_end


def select(t, x, w0, w1):
    m = (t >= w0) & (t <= w1)
    return t[m], x[m]


def rms_deviation(x):
    """s = sqrt(sum (x_i - mean)^2 / (N - 1))."""
    x = np.asarray(x, dtype=float)
    return float(np.sqrt(np.sum((x - x.mean()) ** 2) / (x.size - 1)))


def uniform(t, x):
    """The signal on a uniform grid of its median spacing, linearly
    interpolated. The probe writes every CFD step, but its times are
    printed to a few digits, so even with a fixed step the median spacing
    differs from the step in the last digits and the grid's points fall
    between the samples (close to them: the values change little)."""
    t = np.asarray(t, dtype=float)
    x = np.asarray(x, dtype=float)
    dt = float(np.median(np.diff(t)))
    n = int(np.floor((t[-1] - t[0]) / dt + 1e-9)) + 1
    tu = t[0] + dt * np.arange(n)
    return tu, np.interp(tu, t, x), dt


def amplitude_spectrum(t, x):
    """One-sided amplitude spectrum of x - mean: frequencies [Hz] and
    amplitudes (a sine of amplitude a gives a peak of a at its frequency
    when the window holds a whole number of periods; the DC bin and, for
    an even sample count, the Nyquist bin are not doubled)."""
    tu, xu, dt = uniform(t, x)
    xu = xu - xu.mean()
    X = np.fft.rfft(xu)
    f = np.fft.rfftfreq(xu.size, dt)
    a = 2.0 * np.abs(X) / xu.size
    a[0] /= 2.0
    if xu.size % 2 == 0:
        a[-1] /= 2.0
    return f, a


def dominant_frequency(f, a, fmin=0.0):
    """The frequency of the largest amplitude above fmin (DC excluded)."""
    m = f > max(fmin, 0.0)
    if not np.any(m):
        return float("nan")
    return float(f[m][np.argmax(a[m])])


def plateau_statistics(tp, p, th, h, windows, skip_start, skip_end, fmin=0.0):
    """Per plateau (velocity, t0, t1): rms of p, dominant frequency, mean and
    maximum of h, in the window without skip_start and skip_end. Rows of
    dicts; a plateau whose window holds fewer than 3 samples is left out,
    and one whose samples end before its window does (a run still going)
    has "complete" False."""
    rows = []
    for u, t0, t1 in windows:
        w0, w1 = window(t0, t1, skip_start, skip_end)
        ts, ps = select(tp, p, w0, w1)
        hs = select(th, h, w0, w1)[1]
        if ts.size < 3 or hs.size < 1:
            continue
        f, a = amplitude_spectrum(ts, ps)
        step = float(np.median(np.diff(ts)))
        rows.append({"u": u, "w0": w0, "w1": w1, "n": int(ts.size),
                     "complete": bool(ts[-1] >= w1 - 2 * step),
                     "rms": rms_deviation(ps),
                     "fdom": dominant_frequency(f, a, fmin),
                     "hmean": float(np.mean(hs)), "hmax": float(np.max(hs)),
                     "f": f, "a": a})
    return rows


def moving_average(t, x, width):
    """x averaged over centred windows of `width` seconds (on the signal's
    uniform grid of its median spacing); full windows only, so the result
    starts and ends half a width inside the signal, and is empty when the
    signal is shorter than one window."""
    tu, xu, dt = uniform(t, x)
    n = max(1, int(round(width / dt)))
    if xu.size < n:
        return np.empty(0), np.empty(0)
    xs = np.convolve(xu, np.ones(n) / n, mode="valid")
    return tu[0] + dt * ((n - 1) / 2 + np.arange(xs.size)), xs


def ramp_onset(tp, p, th, h, tu, u, t_end, width=0.05, rise=0.002, u_fixed=()):
    """The start of spouting on the inlet's ramp (0 to t_end), from the
    signals of one run: the gauge pressure p (times tp), the highest
    particle h (times th, its first sample the filled bed at rest) and the
    inlet velocity u (times tu, rising on the ramp).

    - onset: the first sample at which the highest particle stands more
      than `rise` [m] above its first sample (the bed's top starts to
      move), with the inlet velocity then;
    - peak: the largest `width`-second moving average of p on the ramp,
      its time and inlet velocity (the bed's largest pressure drop, as the
      spout breaks through);
    - fixed: the `width`-second average of p when the inlet reaches each
      velocity of u_fixed, NaN where that is at or past the onset or
      outside the averaged signal (the fixed bed's pressure, which its
      packing sets);
    - ts, ps: the moving average on the ramp.

    "complete": the onset is found, and either the data reach t_end (the
    peak is final) or the peak's average ends more than `width` before
    the last one does (the pressure has fallen from it: the spout broke
    through). The second is a judgement, not a proof: a later, higher
    average before t_end is still possible, and the figures of a run that
    has not reached t_end are provisional. NaN throughout where the data
    are shorter than one average."""
    tp, p, th, h, tu, u = (np.asarray(a, dtype=float) for a in (tp, p, th, h, tu, u))
    nan = float("nan")
    ts, ps = moving_average(*select(tp, p, 0.0, t_end), width)
    out = {"p_peak": nan, "t_peak": nan, "u_peak": nan, "t_onset": nan, "u_onset": nan,
           "complete": False, "fixed": [(float(uf), nan) for uf in u_fixed],
           "ts": ts, "ps": ps}
    if not ts.size:
        return out
    k = int(np.argmax(ps))
    out.update(p_peak=float(ps[k]), t_peak=float(ts[k]), u_peak=float(np.interp(ts[k], tu, u)))
    above = np.nonzero((h > h[0] + rise) & (th <= t_end))[0]
    if not above.size:
        return out
    t_on = float(th[above[0]])
    out.update(t_onset=t_on, u_onset=float(np.interp(t_on, tu, u)),
               complete=bool(tp[-1] >= t_end or ts[k] < ts[-1] - width))
    fixed = []
    for uf in u_fixed:
        reached = np.nonzero(u >= uf)[0]
        tf = float(tu[reached[0]]) if reached.size else nan
        ok = uf < out["u_onset"] and ts[0] <= tf <= ts[-1]
        fixed.append((float(uf), float(np.interp(tf, ts, ps)) if ok else nan))
    out["fixed"] = fixed
    return out
