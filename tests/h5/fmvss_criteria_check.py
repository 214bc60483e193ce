"""The FMVSS 208 table of a shipped deck (issue 18; docs/injury.md) against a
computation of its own from the HDF5 file: the unfiltered 10 kHz channels
(/channels) filtered here as SAE J211-1 specifies (numpy, written apart from
src/c6_output/channel_filter.f90, the start-up as docs/injury.md states it),
then HIC15 and HIC36 by brute force over every window of the grid, GSI, the
cumulative 3 ms clip, the chest's deflection and VC, Nij with FMVSS 208
S6.6's intercepts, the neck's and femur's peaks, each against /summary/criteria (value, time, limit, pass);
the unfiltered column against /summary/injury_criteria.

Usage: fmvss_criteria_check.py HSRI2D DECK WORK_DIRECTORY
"""
import math
import os
import shutil
import subprocess
import sys

import h5py
import numpy as np

NAME = "fmvss_criteria"


def fail(message):
    print(f"{NAME}: FAIL: {message}", file=sys.stderr)
    sys.exit(1)


def j211(x, cfc, dt):
    """J211-1 Appendix C, forward then backward, over the record extended at
    each end by its point reflection (10 ms, or until the filter's transient
    falls to 1e-13), each pass starting settled at its first value."""
    wd = 2.0 * math.pi * cfc * 2.0775
    wa = math.sin(wd * dt / 2.0) / math.cos(wd * dt / 2.0)
    den = 1.0 + math.sqrt(2.0) * wa + wa * wa
    a0 = wa * wa / den
    a1, a2 = 2.0 * a0, a0
    b1 = -2.0 * (wa * wa - 1.0) / den
    b2 = (-1.0 + math.sqrt(2.0) * wa - wa * wa) / den
    n = len(x)
    pad = max(1, round(0.010 / dt), math.ceil(math.log(1e-13) / math.log(math.sqrt(-b2))))
    slope = (x[-1] - x[0]) / (n - 1)
    head = [2 * x[0] - x[i] if i <= n - 1 else None for i in range(1, pad + 1)]
    tail = [2 * x[-1] - x[-1 - i] if i <= n - 1 else None for i in range(1, pad + 1)]
    for i in range(pad):
        if head[i] is None:
            head[i] = head[i - 1] - slope
            tail[i] = tail[i - 1] + slope
    w = np.concatenate([np.array(head[::-1]), np.asarray(x, float), np.array(tail)])

    def one_pass(v):
        y = np.empty_like(v)
        x1 = x2 = y1 = y2 = v[0]
        for i, x0 in enumerate(v):
            y0 = a0 * x0 + a1 * x1 + a2 * x2 + b1 * y1 + b2 * y2
            x2, x1, y2, y1 = x1, x0, y1, y0
            y[i] = y0
        return y

    w = one_pass(w)
    w = one_pass(w[::-1])[::-1]
    return w[pad:pad + n]


def hic(t, a, window):
    """max over grid windows of (t2 - t1) (mean a)^2.5, a linear between samples."""
    v = np.concatenate([[0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * np.diff(t))])
    best, where = 0.0, (0.0, 0.0)
    m_max = int(round(window / (t[1] - t[0])))
    for m in range(1, m_max + 1):
        dv = v[m:] - v[:-m]
        dt = t[m:] - t[:-m]
        h = dt * np.power(np.maximum(dv, 0.0) / dt, 2.5)
        k = int(np.argmax(h))
        if h[k] > best * (1 + 1e-12):
            best, where = h[k], (t[k], t[k + m])
    return best, where


def clip3ms(t, a):
    """the level spent at or above for a cumulative 3 ms, a linear between samples."""
    def time_above(level):
        total = 0.0
        for i in range(len(a) - 1):
            lo, hi, d = min(a[i], a[i + 1]), max(a[i], a[i + 1]), t[i + 1] - t[i]
            if lo >= level:
                total += d
            elif hi > level:
                total += d * (hi - level) / (hi - lo)
        return total
    lo, hi = 0.0, float(a.max())
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if time_above(mid) >= 3e-3:
            lo = mid
        else:
            hi = mid
    return lo


def main():
    exe, deck, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    p = subprocess.run([exe, deck, "-o", os.path.join(work, "run.lst"), "--h5", os.path.join(work, "run.h5")],
                       capture_output=True, text=True, timeout=600)
    if p.returncode != 0:
        fail(f"the run failed: {p.stderr}")
    with h5py.File(os.path.join(work, "run.h5"), "r") as f:
        c = f["summary/criteria"]
        names = list(c.attrs["columns"])
        rows = list(c.attrs["rows"])
        table = {n: dict(zip(rows, c[:, j])) for j, n in enumerate(names)}
        classes = dict(zip(names, c.attrs["filter_class"]))
        units = dict(zip(names, c.attrs["units"]))
        ch = f["channels"]
        t = ch["time"][()]
        dt = t[1] - t[0]
        if abs(dt - 1e-4) > 1e-12 or not np.allclose(np.diff(t), dt, rtol=0, atol=1e-12):
            fail("the channels' grid is not 10 kHz")
        # the head's on its own 20 kHz grid (CFC 1000's corridor, docs/injury.md)
        th = ch["head_time"][()]
        dth = th[1] - th[0]
        if abs(dth - 5e-5) > 1e-12 or not np.allclose(np.diff(th), dth, rtol=0, atol=1e-12):
            fail("the head's grid is not 20 kHz")
        head = ch["head_acceleration"][()]
        chest = ch["chest_acceleration"][()]
        neck = ch["neck_loads"][()]
        femur = ch["femur_force"][()]
        deflection = ch["chest_deflection"][()]
        unf = f["summary/injury_criteria"]
        unfiltered = dict(zip(list(unf.attrs["columns"]), unf[0, :]))
        # the loads' channels against the joint tensions of the print
        # records, which another path computes (output_producers'
        # bone_components_at): at the print times, states of the run, the
        # neck's axial force is FT_4 and one femur's compression -FT_1/2,
        # lbf to N (+ tension for the neck, + compression for the femur)
        # (a run whose last step ends a rounding short of TMAX has no grid
        # point there)
        tp = f["time"][()]
        keep = tp <= t[-1] + 1e-12
        tp = tp[keep]
        ft = f["joints/tension"][()][keep]
        at = [int(np.argmin(np.abs(t - x))) for x in tp]
        if len(tp) < 10 or np.max(np.abs(t[at] - tp)) > 1e-12:
            fail("the print times are not on the channels' grid")
        lbf = 4.4482216152605
        scale = max(1.0, float(np.max(np.abs(ft[:, [0, 3]]))) * lbf)
        if np.max(np.abs(neck[at, 0] - ft[:, 3] * lbf)) > 1e-9 * scale:
            fail("the neck's axial force is not FT_4 of /joints/tension at the print times")
        if np.max(np.abs(femur[at] + ft[:, 0] * lbf / 2.0)) > 1e-9 * scale:
            fail("the femur's force is not -FT_1/2 of /joints/tension at the print times")

    def check(name, value, rel, at=None, cfc=None, unit=None):
        got = table[name]["value"]
        if not abs(got - value) <= rel * max(1.0, abs(value)):
            fail(f"{name}: the table has {got!r}, this computation {value!r}")
        if at is not None and abs(table[name]["time"] - at) > 1.5e-4:
            fail(f"{name}: at t = {table[name]['time']!r}, this computation {at!r}")
        if cfc is not None and classes[name] != cfc:
            fail(f"{name}: filter class {classes[name]!r}, expected {cfc!r}")
        if unit is not None and units[name] != unit:
            fail(f"{name}: unit {units[name]!r}, expected {unit!r}")
        limit = table[name]["limit"]
        if not math.isnan(limit):
            passed = 1.0 if got <= limit else 0.0
            if table[name]["pass"] != passed:
                fail(f"{name}: pass is {table[name]['pass']!r} for {got!r} against {limit!r}")
        print(f"{name:20s} {got:14.6f} {value:14.6f}")

    # FMVSS 208 S6's 50th male limits, the defaults of *FMVSS208
    for name, limit in (("head_hic15", 700.0), ("chest_clip3ms", 60.0), ("chest_deflection", 63.0),
                        ("neck_nij", 1.0), ("neck_tension", 4170.0), ("neck_compression", 4000.0),
                        ("femur_compression", 10008.0)):
        if table[name]["limit"] != limit:
            fail(f"{name}: limit {table[name]['limit']!r}, expected {limit!r}")

    a_head = np.hypot(j211(head[:, 0], 1000, dth), j211(head[:, 1], 1000, dth))
    h15, w15 = hic(th, a_head, 0.015)
    h36, w36 = hic(th, a_head, 0.036)
    check("head_hic15", h15, 1e-9, at=w15[0], cfc="CFC 1000", unit="1")
    if abs(table["head_hic15"]["time_end"] - w15[1]) > 1.5e-4:
        fail(f"head_hic15's window ends at {table['head_hic15']['time_end']!r}, here {w15[1]!r}")
    check("head_hic36", h36, 1e-9, at=w36[0], cfc="CFC 1000")
    gsi = float(np.sum(0.5 * (a_head[1:] ** 2.5 + a_head[:-1] ** 2.5) * np.diff(th)))
    check("head_gsi", gsi, 1e-9)

    a_chest = np.hypot(j211(chest[:, 0], 180, dt), j211(chest[:, 1], 180, dt))
    check("chest_clip3ms", clip3ms(t, a_chest), 1e-7, cfc="CFC 180", unit="g")
    check("chest_gsi", float(np.sum(0.5 * (a_chest[1:] ** 2.5 + a_chest[:-1] ** 2.5) * np.diff(t))), 1e-9)

    fz = j211(neck[:, 0], 600, dt)
    my = j211(neck[:, 1], 600, dt)
    nij = np.abs(fz) / np.where(fz >= 0, 6806.0, 6160.0) + np.abs(my) / np.where(my >= 0, 310.0, 135.0)
    k = int(np.argmax(nij))
    check("neck_nij", nij[k], 1e-9, at=t[k], cfc="CFC 600", unit="1")
    k = int(np.argmax(fz))
    check("neck_tension", max(fz[k], 0.0), 1e-9, at=t[k] if fz[k] > 0 else None, unit="N")
    k = int(np.argmin(fz))
    check("neck_compression", max(-fz[k], 0.0), 1e-9, at=t[k] if fz[k] < 0 else None, unit="N")
    ff = j211(femur, 600, dt)
    k = int(np.argmax(ff))
    check("femur_compression", max(ff[k], 0.0), 1e-9, at=t[k] if ff[k] > 0 else None, cfc="CFC 600", unit="N")

    d = j211(deflection, 180, dt)
    k = int(np.argmax(d))
    check("chest_deflection", d[k], 1e-9, at=t[k], cfc="CFC 180", unit="mm")
    rate = np.gradient(d, t, edge_order=1) / 1000.0          # m/s (central inside, one-sided at the ends)
    vc = 1.3 * rate * (d / 1000.0) / 0.229
    k = int(np.argmax(vc))
    check("chest_vc", vc[k], 1e-9, at=t[k], cfc="CFC 180", unit="m/s")

    # the accepted steps' unfiltered values beside them
    for name, key in (("head_hic15", "head_hic15"), ("head_hic36", "head_hic36"), ("head_gsi", "head_gsi"),
                      ("chest_gsi", "chest_gsi"), ("chest_clip3ms", "chest_clip3ms")):
        if table[name]["unfiltered"] != unfiltered[key]:
            fail(f"{name}: unfiltered {table[name]['unfiltered']!r}, /summary/injury_criteria {unfiltered[key]!r}")
    # filtering a smooth run moves the criteria little
    if not abs(table["head_hic15"]["value"] - unfiltered["head_hic15"]) < 0.05 * unfiltered["head_hic15"]:
        fail("the filtered HIC15 is far from the unfiltered one")
    print(f"{NAME}: ok")


if __name__ == "__main__":
    main()
