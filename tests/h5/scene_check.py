"""The HDF5 file's /scene tables (issue 18, the pictures' geometry) against
what the run computed: the segments give every joint of /joints/x, /joints/y
from the hip and /body/theta at every record; the belts' anchors and h give
/effects/*_belt/angle (figure 17, BE-2); the surfaces and the contact arcs
are the listing's INTERIOR SURFACES and TABLE 1 - CONTACT ARCS; the seat's
front edge and cushion angle are the deck's.

    scene_check.py HSRI2D DECKS_DIR WORKDIR
"""
import math
import os
import subprocess
import sys

import h5py
import numpy as np

hsri2d, decks, work = sys.argv[1:4]
os.makedirs(work, exist_ok=True)
failures = []


def check(ok, what):
    print(("ok: " if ok else "FAIL: ") + what)
    if not ok:
        failures.append(what)


def run(deck):
    lst, h5 = os.path.join(work, deck + ".lst"), os.path.join(work, deck + ".h5")
    p = subprocess.run([hsri2d, deck + ".deck", "-o", lst, "--h5", h5], cwd=decks, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"hsri2d {deck}.deck failed ({p.returncode}): {p.stderr}")
    return lst, h5


def table(listing, title, first_col_int=True):
    rows, inside = [], False
    with open(listing, encoding="utf-8") as f:
        for line in f:
            if line.startswith(" " + title):
                inside = True
                continue
            if inside:
                fields = line.split()
                if not fields:
                    if rows:
                        break
                    continue
                if fields[0].isdigit():
                    rows.append(line)
    return rows


def e(a):
    return np.stack([np.cos(a), np.sin(a)], axis=-1)


# the default deck: seat, lap and torso belts, the driver's interior
lst, h5 = run("default")
with h5py.File(h5, "r") as f:
    sc = f["scene"]
    check(set(sc) == {"segments", "body_points", "surfaces", "belts", "seat"}, "the five scene tables")
    for name in sc:
        d = sc[name]
        check(all(k in d.attrs for k in ("columns", "units", "description", "rows"))
              and len(d.attrs["rows"]) == d.shape[0] and len(d.attrs["columns"]) == d.shape[1],
              f"/scene/{name}: columns, units, description and a label per row")
    theta = f["body/theta"][:]
    jx, jy = f["joints/x"][:], f["joints/y"][:]
    joints = np.stack([jx, jy], axis=-1)                      # (n, 7, 2)
    seg = sc["segments"][:]
    L = seg[:, 1]
    # the chain of body_kinematics: each joint from the one below it
    pred = {2: joints[:, 0] + L[0] * e(theta[:, 0]),          # lower spine
            3: joints[:, 1] + L[1] * e(theta[:, 1]),          # upper spine
            4: joints[:, 2] + L[2] * e(theta[:, 2]),          # neck: L_3 along segment 3
            5: joints[:, 2] + L[3] * e(theta[:, 2]),          # shoulder: L_4 along segment 3
            6: joints[:, 4] + L[4] * e(theta[:, 4]),          # elbow
            7: joints[:, 0] + L[6] * e(theta[:, 6])}          # knee
    worst = max(np.abs(pred[j] - joints[:, j - 1]).max() for j in pred)
    check(worst < 1e-9 * max(1.0, np.abs(joints).max()),
          f"the segments give every joint at every record (worst {worst:.2e} in)")
    check(list(seg[:, 0].astype(int)) == [1, 2, 3, 4, 5, 6, 1, 7], "each segment's proximal joint")

    belts = sc["belts"][:]
    angle = {1: f["effects/lap_belt/angle"][:], 2: f["effects/torso_belt/angle"][:, 0],
             3: f["effects/torso_belt/angle"][:, 1]}
    for row in belts:
        j, kind, s, jt, ax, ay, h = row
        j, kind, s, jt = int(j), int(kind), int(s), int(jt)
        if kind == 2:
            p = joints[:, jt - 1] + h * e(theta[:, s - 1])
            phi = np.arctan2(p[:, 1] - ay, p[:, 0] - ax)
        else:
            u, v = joints[:, 0, 0] - ax, joints[:, 0, 1] - ay
            phi = np.arcsin(h / np.hypot(u, v)) + np.arctan2(v, u)
        diff = np.abs(np.angle(np.exp(1j * (phi - angle[j])))).max()
        check(diff < 1e-9, f"belt section {j}: the anchor and h give the belt's angle at every record "
                           f"(worst {diff:.2e} rad)")

    sf = sc["surfaces"][:]
    rows = table(lst, "INTERIOR SURFACES")
    listed = {int(r[0:4]): [float(v) for v in r[39:].split()] for r in rows}
    check(sorted(listed) == list(sf[:, 0].astype(int)), "the surfaces are the listing's, in its order")
    worst = 0.0
    for row in sf:
        k, kind, x, y, psi, d = row[:6]
        lx, ly, lpsi, ld = listed[int(k)][:4]
        worst = max(worst, abs(x - lx), abs(y - ly), abs(math.degrees(psi) - lpsi) / 100, abs(d - ld))
    check(worst < 1e-3, f"each surface's X'', Y'', PSI, D as the listing prints them (worst {worst:.1e})")
    check(list(sc["surfaces"].attrs["rows"][:2]) == ["head rest", "windshield"], "the surfaces' names")

    bp = sc["body_points"][:]
    arcs = {int(r.split()[0]): r for r in table(lst, "TABLE 1 - CONTACT ARCS")}
    r_listed = [float(arcs[i][18:30]) for i in range(1, 12)]
    r_expected = list(r_listed)
    r_expected[8] = r_listed[6]                                # the shin drawn from the knee's circle (D-C2)
    check(np.allclose(bp[:, 4], r_expected, rtol=1e-4), "the contact arcs' radii are TABLE 1's")
    rho2, gam2 = float(arcs[2][30:42]), math.radians(float(arcs[2][42:56]))
    check(abs(bp[1, 2] - rho2 * math.cos(gam2)) < 1e-3 and abs(bp[1, 3] - rho2 * math.sin(gam2)) < 1e-3,
          "the upper back's centre at rho' and gamma from the torso line")
    seat = sc["seat"][:]
    check(seat.shape == (1, 9) and seat[0, 0] == 1 and abs(seat[0, 1] - 14.0) < 1e-12,
          "the spring seat, its front edge at z_o = 14 in")

# a deck without belts, seat or interior: empty tables, not missing ones
lst, h5 = run("body_only")
with h5py.File(h5, "r") as f:
    shapes = {n: f["scene"][n].shape for n in f["scene"]}
    check(shapes["surfaces"] == (0, 8) and shapes["belts"] == (0, 7) and shapes["seat"] == (0, 9)
          and shapes["segments"] == (8, 3), f"body_only: empty surfaces, belts and seat ({shapes})")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("the scene tables agree with the run")
