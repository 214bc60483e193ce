#!/usr/bin/env python3
"""hsri2d against a general physics engine (MuJoCo) on the same occupant.

The mission asks hsri2d to be faster than a general physics engine on the
same model. This script builds, in MuJoCo, the closest analogues of three
benchmark decks and times both programs in CPU time (medians of interleaved
rounds):

  body    tools/bench/body_alone.deck: the eight segments and ten degrees of
          freedom of Table 1 (masses, inertias, lengths, centres of gravity),
          joint springs at rest in the initial posture, gravity, the initial
          rates of the deck;
  belted  decks/belted_driver.deck: that body with joint friction and stops,
          in a vehicle stopped from 30 mph by a half-sine pulse, held by a lap
          belt over the pelvis and a torso belt (buckle - lower chest - D-ring)
          whose webbing pulls past its slack;
  interior decks/default.deck: the sitting driver, his belts, a seat cushion
          and the twenty contact pairs of Tables 7-8 (body points as spheres of
          the *ARCS radii, the shin a capsule; the surfaces of the deck's
          listing as thin boxes on the vehicle).

and, like for like (issue 16 section 5): the belted analogue without joint
friction and stops in both programs (hsri2d: the deck's *JOINTS with C' = 0,
stops and dislocation limits at +-360 deg and no stop stiffness; MuJoCo: no
frictionloss and no joint limits), beside the belted case with them in both.

All with classic RK4 at a step of 1e-4 s for 0.2 s (2000 steps). The MuJoCo
models are simpler than hsri2d's: linear webbing springs without hysteresis,
shared deflection or load limiter, contacts by MuJoCo's soft constraints
rather than Table 4's materials, friction and the seat by contact. They have
the same numbers of bodies, joints, belts and contact pairs, which is what
sets the cost of an evaluation, and they move alike (the script prints the
belts' stretch and the contacts' count to show that the belts pull and the
body strikes). Use the result as an order of magnitude.

  python3 -m venv /tmp/mj && /tmp/mj/bin/pip install mujoco h5py
  /tmp/mj/bin/python tools/bench/engine_comparison.py [--repeat N] [--rounds R]
  /tmp/mj/bin/python tools/bench/engine_comparison.py --accuracy

--accuracy: time to accuracy on the belted analogue, each program on its own
model against its own refined run (RK4 at 2e-6 s, about 1/16 of the finest step): the
largest joint-angle error (alpha_i - alpha_m, all seven joints, every 5 ms)
and the CPU time of the run, for RK4 over dt (both programs) and, for hsri2d,
Dormand-Prince over RTOL; the cheapest setting within 0.1 deg of each.

hsri2d is timed by build/release/hsri2d_bench --run-only (tools/bench/bench
builds it); docs/performance.md keeps the figures.
"""
import argparse
import math
import os
import statistics
import subprocess
import sys
import time

import numpy as np

try:
    import mujoco
    from mujoco import rollout
except ImportError:
    sys.exit("engine_comparison: needs MuJoCo's Python package (pip install mujoco)")

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.dirname(HERE))
import hsri2d_runs as runs  # noqa: E402  (tools/: the deck's fields)
G = 386.088           # in/s^2
DT, N_STEP = 1.0e-4, 2000

# Table 1 of the decks (docs/anthropometry.md): lb*s^2/in, lb*in*s^2, in
MASS = [0.06337, 0.062031, 0.096394, 0.036148, 0.024991, 0.019636, 0.089254, 0.054445]
INERTIA = [0.6489, 0.5583, 1.952, 0.3253, 0.3427, 0.4924, 2.5351, 2.5651]
LENGTH = [5.0, 6.0, 12.0, 8.0, 11.5, 13.7, 16.5, 16.5]
RHO = [2.5, 3.0, 6.0, 5.1, 5.0, 7.3, 7.1, 10.0]
# joints 1-7: K (in*lb/rad), C' (in*lb), stops OMEGA, BOMEGA on alpha_i - alpha_m (deg)
K = [500.0, 1000.0, 2000.0, 200.0, 100.0, 50.0, 100.0]
CF = [20.0, 20.0, 20.0, 10.0, 10.0, 10.0, 10.0]
STOPS = [(70, 210), (-55, 5), (-35, 20), (-65, 45), (-240, 0), (-5, 150), (-5, 140)]
# the tree: segment -> (parent segment, link length index on the parent or None, joint)
# (body_kinematics: the head on L3 and the arm on L4 along the upper torso)
TREE = {2: (1, 1, 2), 3: (2, 2, 3), 4: (3, 3, 4), 5: (3, 4, 5), 6: (5, 5, 6), 7: (1, None, 1), 8: (7, 7, 7)}
# joint k couples segment k with segment m(k) (model.f90 joint_partner)
PARTNER = {1: 7, 2: 1, 3: 2, 4: 3, 5: 3, 6: 5, 7: 8}

BODY_ALONE = dict(angles=[125, 110, 105, 85, -44, 22, 15, -60],
                  rates=[-100, -150, -200, -1200, 150, 0, 0, 0])
BELTED = dict(angles=[125, 110, 105, 85, -44, 22, 15, -60], rates=[0] * 8)
INTERIOR = dict(angles=[90, 90, 90, 90, -95, -80, 10, -88], rates=[0] * 8)


def children(parent):
    return [c for c, (p, _, _) in sorted(TREE.items()) if p == parent]


def relative_angle(angles, joint):
    """alpha_k - alpha_m(k) of joint k (deg), as the decks' stops read it (Table 6)."""
    return angles[joint - 1] - angles[PARTNER[joint] - 1]


def body_xml(i, posture, friction, extra):
    """Segment i and its subtree. Each body frame has its x axis along the segment
    (a rotation about -y by the segment's angle, so that angles grow from x to z as
    alpha grows from x to y in the report); the root carries the hip's two slides,
    whose axes are the interior's x and z written in the pelvis frame."""
    a = posture["angles"]
    inert = f'<inertial pos="{RHO[i - 1]} 0 0" mass="{MASS[i - 1]}" ' \
            f'diaginertia="{INERTIA[i - 1]} {INERTIA[i - 1]} {INERTIA[i - 1]}"/>'
    if i == 1:
        c, s = math.cos(math.radians(a[0])), math.sin(math.radians(a[0]))
        head = (f'<body name="s1" axisangle="0 -1 0 {a[0]}">'
                f'<joint name="x" type="slide" axis="{c} 0 {-s}"/>'
                f'<joint name="z" type="slide" axis="{s} 0 {c}"/>'
                f'<joint name="a1" type="hinge" axis="0 -1 0"/>')
    else:
        parent, link, joint = TREE[i]
        offset = 0.0 if link is None else LENGTH[link - 1]
        attrs = f'stiffness="{K[joint - 1]}"'
        if friction:
            # the stops as joint limits, the friction as dry friction (C.4.c)
            rel0 = relative_angle(a, joint)
            lo, hi = STOPS[joint - 1]
            sign = 1 if PARTNER[joint] == parent else -1    # hip: thigh on pelvis, partner 7
            lo, hi = sorted((sign * (lo - rel0), sign * (hi - rel0)))
            attrs += f' frictionloss="{CF[joint - 1]}" limited="true" range="{lo} {hi}"'
        head = (f'<body name="s{i}" pos="{offset} 0 0" axisangle="0 -1 0 {a[i - 1] - a[parent - 1]}">'
                f'<joint name="j{joint}" type="hinge" axis="0 -1 0" {attrs}/>')
    return head + inert + extra.get(i, "") + "".join(body_xml(c, posture, friction, extra)
                                                      for c in children(i)) + "</body>"


def initial_velocity(m, posture, v0=0.0):
    v = np.zeros(m.nv)
    r = [math.radians(x) for x in posture["rates"]]
    v[m.joint("a1").dofadr[0]] = r[0]
    for seg, (parent, _, joint) in TREE.items():
        v[m.joint(f"j{joint}").dofadr[0]] = r[seg - 1] - r[parent - 1]
    v[m.joint("x").dofadr[0]] += v0
    if v0:
        v[m.joint("vx").dofadr[0]] = v0
    return v


def mjcf(posture, friction=False, body_extra=None, world="", tail="", contacts=False, dt=DT):
    flags = "" if contacts else '<flag contact="disable"/>'
    return (f'<mujoco><compiler angle="degree"/>'
            f'<option timestep="{dt}" integrator="RK4" gravity="0 0 {-G}">{flags}</option>'
            f'<worldbody>{body_xml(1, posture, friction, body_extra or {})}{world}</worldbody>{tail}</mujoco>')


def local_point(m, d, body, wx, wz):
    """A point given in the interior frame (x forward, z up, from the hip at t = 0)
    in the frame of body, at the initial posture."""
    b = m.body(body).id
    return d.xmat[b].reshape(3, 3).T @ (np.array([wx, 0.0, wz]) - d.xpos[b])


def fmt(v):
    return " ".join(f"{c:.6f}" for c in v)


def pulse(n, v0=528.0, duration=0.1074, peak_g=20.0, dt=DT):
    """The decks' 30 mph frontal pulse: a half-sine of 20 g over 107.4 ms."""
    t = np.arange(n) * dt
    return np.where(t < duration, -peak_g * G * np.sin(math.pi * t / duration), 0.0)


VEHICLE_MASS = 10.36


def vehicle_xml(sites="", geoms=""):
    return (f'<body name="veh"><joint name="vx" type="slide" axis="1 0 0"/>'
            f'<inertial pos="0 0 0" mass="{VEHICLE_MASS}" diaginertia="1 1 1"/>{sites}{geoms}</body>')


def belted_model(posture, anchors, points, stiffness, slack, body_geoms=None, vehicle_geoms="",
                 pairs="", friction=True, dt=DT):
    """The body in a vehicle driven by the pulse (a motor on its slide), three belt
    tendons from vehicle sites to body sites, slack as a dead band of the spring."""
    def build(lengths, where):
        extra = dict(body_geoms or {})
        for name, (seg, _, _) in points.items():
            extra[seg] = extra.get(seg, "") + f'<site name="{name}" pos="{fmt(where[name])}"/>'
        sites = "".join(f'<site name="{n}" pos="{x} 0 {z}"/>' for n, (x, z) in anchors.items())
        ten = "".join(f'<spatial name="belt{j}" stiffness="{k}" springlength="0 {L}">'
                      + "".join(f'<site site="{s}"/>' for s in path) + "</spatial>"
                      for j, (k, L, path) in enumerate(zip(stiffness, lengths, BELT_PATHS), 1))
        tail = f'<tendon>{ten}</tendon><actuator><motor joint="vx" gear="1"/></actuator>'
        if pairs:
            tail += f"<contact>{pairs}</contact>"
        return mujoco.MjModel.from_xml_string(mjcf(posture, friction, extra, vehicle_xml(sites, vehicle_geoms),
                                                   tail, contacts=bool(pairs), dt=dt))
    m = build([1e3] * 3, {n: (0, 0, 0) for n in points})
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    where = {n: local_point(m, d, f"s{seg}", x, z) for n, (seg, x, z) in points.items()}
    m = build([1e3] * 3, where)
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    lengths = [d.ten_length[j] + slack[j] for j in range(3)]
    return build(lengths, where), lengths


# lap: anchor - front of the pelvis - anchor (both sides lumped, as NBELT's j = 1);
# torso: buckle - lower chest, upper chest - D-ring
BELT_PATHS = [("lap_l", "pelvis_front", "lap_r"), ("buckle", "low_chest"), ("chest", "d_ring")]


def belted_driver(friction=True, dt=DT):
    anchors = {"lap_l": (-6.88, -9.83), "lap_r": (-6.88, -9.83), "buckle": (-3.0, -2.0), "d_ring": (-16.0, 23.0)}
    posture = BELTED
    a = [math.radians(x) for x in posture["angles"]]
    # body points at the belts' h_j: 3.4 in ahead of the hip, 3 in up segment 2, 9 in up segment 3
    p2 = (LENGTH[0] * math.cos(a[0]) + 3 * math.cos(a[1]), LENGTH[0] * math.sin(a[0]) + 3 * math.sin(a[1]))
    p3 = (LENGTH[0] * math.cos(a[0]) + LENGTH[1] * math.cos(a[1]) + 9 * math.cos(a[2]),
          LENGTH[0] * math.sin(a[0]) + LENGTH[1] * math.sin(a[1]) + 9 * math.sin(a[2]))
    points = {"pelvis_front": (1, 3.4, 0.0), "low_chest": (2, *p2), "chest": (3, *p3)}
    return belted_model(posture, anchors, points, [2500.0, 1250.0, 800.0], [0.25, 0.25, 0.5],
                        friction=friction, dt=dt)


# the default deck's interior, from its listing (INTERIOR SURFACES): k -> ends (x, y)
SURFACES = {1: ((-8.9, 29.1), (-8.9, 35.1)), 2: ((12.0, 36.0), (37.981, 21.0)), 3: ((11.0, 35.5), (13.052, 29.862)),
            5: ((24.5, 10.0), (21.499, -2.0)), 6: ((31.0, -6.6), (21.002, -16.598)),
            8: ((22.25, 16.38), (20.377, 11.744)), 9: ((-3.5, -3.0), (-3.5, 24.0)),
            10: ((22.0, 22.42), (16.006, 7.585)), 11: ((-20.0, 36.0), (40.0, 36.0)),
            12: ((-20.0, -16.598), (40.0, -16.598)), 25: ((21.499, -2.0), (21.499, -2.0)),
            30: ((20.502, 18.711), (17.505, 11.294))}
# body points i = 1..10: segment, distance along it, radius (*ARCS; contacts.md D-C1)
POINTS = {1: (1, 0.0, 3.4), 2: (3, 7.0, 2.5), 3: (3, 7.3, 5.0), 4: (4, 6.1, 3.9), 5: (5, 0.0, 2.5),
          6: (5, 11.5, 1.5), 7: (7, 16.5, 2.0), 8: (8, 16.5, 2.9), 9: (8, 8.0, 1.5), 10: (6, 13.7, 1.5)}
# the driver's twenty pairs (Tables 7-8; the listing's CONTACT PAIRS OF NBODY 1)
PAIRS = [(1, 9), (2, 9), (3, 8), (3, 10), (4, 1), (4, 2), (4, 3), (4, 8), (4, 9), (4, 10), (4, 11), (5, 30),
         (6, 9), (7, 5), (8, 6), (8, 12), (9, 25), (10, 5), (10, 30), (10, 11)]


def interior_driver():
    posture = INTERIOR
    a = [math.radians(x) for x in posture["angles"]]

    def along(*links):
        x = sum(L * math.cos(a[s - 1]) for s, L in links)
        return x, sum(L * math.sin(a[s - 1]) for s, L in links)
    anchors = {"lap_l": (-6.88, -9.83), "lap_r": (-6.88, -9.83), "buckle": (-3.0, -2.0)}
    shoulder = along((1, LENGTH[0]), (2, LENGTH[1]), (3, LENGTH[3]))
    anchors["d_ring"] = (shoulder[0] - 9.0, shoulder[1] + 5.5)
    points = {"pelvis_front": (1, 1.0, 0.0), "low_chest": (2, *along((1, LENGTH[0]), (2, 3.0))),
              "chest": (3, *along((1, LENGTH[0]), (2, LENGTH[1]), (3, 9.0)))}
    body_geoms = {}
    for i, (seg, dist, r) in POINTS.items():
        if i == 9:      # the shin: a capsule along segment 8
            g = f'<geom name="p9" type="capsule" fromto="2 0 0 {LENGTH[7] - 2} 0 0" size="{r}"/>'
        else:
            g = f'<geom name="p{i}" type="sphere" pos="{dist} 0 0" size="{r}"/>'
        body_geoms[seg] = body_geoms.get(seg, "") + g
    geoms = ""
    for k, ((x0, y0), (x1, y1)) in SURFACES.items():
        if (x0, y0) == (x1, y1):
            geoms += f'<geom name="k{k}" type="sphere" pos="{x0} 0 {y0}" size="0.25"/>'
        else:
            geoms += f'<geom name="k{k}" type="box" fromto="{x0} 0 {y0} {x1} 0 {y1}" size="0.25 8"/>'
    # the seat cushion under the hip and the thighs
    geoms += '<geom name="seat" type="box" pos="6 0 -4.4" size="10 8 1"/>'
    pairs = "".join(f'<pair geom1="p{i}" geom2="k{k}"/>' for i, k in PAIRS)
    pairs += '<pair geom1="p1" geom2="seat"/><pair geom1="p7" geom2="seat"/>'
    m, lengths = belted_model(posture, anchors, points, [2500.0, 1250.0, 800.0], [0.1, 0.1, 0.25],
                              body_geoms, geoms, pairs)
    for g in range(m.ngeom):            # only the pairs above collide
        m.geom_contype[g] = 0
        m.geom_conaffinity[g] = 0
    return m, lengths


def mujoco_cpu(m, v, ctrl, repeat, nstep=N_STEP):
    d = mujoco.MjData(m)
    d.qvel[:] = v
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    s0 = np.zeros(mujoco.mj_stateSize(m, spec))
    mujoco.mj_getState(m, d, s0, spec)
    times = []
    for _ in range(repeat):
        t0 = time.process_time()
        rollout.rollout(m, d, s0, control=ctrl, nstep=nstep)
        times.append(time.process_time() - t0)
    return statistics.median(times)


JOINT_CHAIN = {k: (seg, parent) for seg, (parent, _, k) in TREE.items()}


def mujoco_angles(m, v, ctrl, dt, every):
    """alpha_k - alpha_m(k) (rad) of the seven joints at every `every` s, with the
    initial relative angles removed (MuJoCo's hinges start at 0): each row the
    hinge angle with the sign of the decks' pairing."""
    d = mujoco.MjData(m)
    d.qvel[:] = v
    n = int(round(0.2 / dt))
    stride = int(round(every / dt))
    rows = []
    for k in range(n + 1):
        if k % stride == 0:
            rows.append([d.qpos[m.joint(f"j{j}").qposadr[0]] for j in range(1, 8)])
        if k == n:
            break
        d.ctrl[0] = ctrl[k, 0]
        mujoco.mj_step(m, d)
    return np.array(rows)


def smooth_deck(text):
    """decks/belted_driver.deck without joint friction and stops: *JOINTS with C' = 0,
    the stops at -+360 deg without stiffness, *RESTRAINTS' dislocation limits there too."""
    out, group = [], None
    for line in text.splitlines():
        if line.startswith("*"):
            group = line.split()[0]
        elif group == "*JOINTS" and line[:2].strip().isdigit():
            line = line[:12] + f"{0.0:10.1f}" + line[22:32] + f"{-360.0:10.1f}{360.0:10.1f}{0.0:10.1f}{0.0:10.1f}"
        elif group == "*RESTRAINTS" and line[:2].strip().isdigit():
            line = line[:52].ljust(52) + f"{-360.0:10.1f}{360.0:10.1f}"
        out.append(line)
    return "\n".join(out) + "\n"


def with_time(text, dt=None, rtol=None):
    """The deck with its *TIME card's DT (RK4) or RTOL (Dormand-Prince, ATOL = RTOL/100)
    and its *OPTIONS NINT set (the fields of tools/hsri2d_runs.py)."""
    out, group, card = [], None, 0
    for line in text.splitlines():
        if line.startswith("*"):
            group, card = line.split()[0], 0
        elif group in ("*TIME", "*OPTIONS") and line.strip() and not line.startswith("$"):
            card += 1
            if card == 1 and group == "*OPTIONS":
                line = runs.NINT.put(line, "2" if dt else "3").rstrip()
            if card == 1 and group == "*TIME":
                if dt:
                    line = runs.DT.put(line, runs.number_text(dt))
                else:
                    line = runs.ATOL.put(runs.RTOL.put(line, runs.number_text(rtol)), runs.number_text(runs.tidy(rtol / 100)))
                line = line.rstrip()
        out.append(line)
    return "\n".join(out) + "\n"


def hsri2d_angles(program, deck, every):
    """Run the program on deck (its HDF5 file): the joint angles every `every` s."""
    import h5py
    h5 = deck[:-5] + ".h5"
    subprocess.run([program, deck, "-o", os.devnull, "--h5", h5], check=True, capture_output=True)
    with h5py.File(h5, "r") as f:
        t, a = f["time"][:], f["joints/angle"][:]
    keep = [i for i, ti in enumerate(t) if abs(ti / every - round(ti / every)) < 1e-6]
    return a[keep]


def accuracy(args):
    import tempfile
    print("time to accuracy on the belted analogue: each program against its own refined run; largest "
          "joint-angle error (deg) every 5 ms; CPU ms of the run (hsri2d: the simulation alone, "
          f"hsri2d_bench --run-only; MuJoCo: rollout), medians of {args.repeat}")
    with open(os.path.join(TOP, "decks/belted_driver.deck")) as f:
        base = f.read()
    dts = [5e-4, 2.5e-4, 1.25e-4, 6.25e-5, 3.125e-5]     # (DTPRINT 5 ms a multiple of each)
    ref_dt = 2.0e-6                    # (a divisor of 5 ms; about dts[-1] / 16)
    every = 5e-3
    with tempfile.TemporaryDirectory() as work:
        for label, friction in (("with joint friction and stops", True), ("without", False)):
            text = base if friction else smooth_deck(base)
            program = os.path.join(os.path.dirname(args.bench), "hsri2d")

            def write(name, body):
                path = os.path.join(work, name + ".deck")
                with open(path, "w") as f:
                    f.write(body)
                return path
            ref = hsri2d_angles(program, write(f"ref{friction}", with_time(text, dt=ref_dt)), every)
            rows = []
            for dt in dts:
                deck = write(f"rk4_{dt:g}_{friction}", with_time(text, dt=dt))
                err = np.degrees(np.abs(hsri2d_angles(program, deck, every) - ref)).max()
                rows.append(("hsri2d RK4", f"dt {dt:g}", err, hsri2d_cpu(args.bench, [deck], args.repeat)[os.path.basename(deck)]))
            for rtol in [1e-4, 1e-5, 1e-6, 1e-7, 1e-8]:
                deck = write(f"dp_{rtol:g}_{friction}", with_time(text, rtol=rtol))
                err = np.degrees(np.abs(hsri2d_angles(program, deck, every) - ref)).max()
                rows.append(("hsri2d DP", f"RTOL {rtol:g}", err, hsri2d_cpu(args.bench, [deck], args.repeat)[os.path.basename(deck)]))
            m_ref, _ = belted_driver(friction, ref_dt)
            n_ref = int(round(0.2 / ref_dt))
            ctrl = (VEHICLE_MASS * pulse(n_ref, dt=ref_dt)).reshape(n_ref, 1)
            mref = mujoco_angles(m_ref, initial_velocity(m_ref, BELTED, 528.0), ctrl, ref_dt, every)
            for dt in dts:
                m, _ = belted_driver(friction, dt)
                n = int(round(0.2 / dt))
                ctrl = (VEHICLE_MASS * pulse(n, dt=dt)).reshape(n, 1)
                v = initial_velocity(m, BELTED, 528.0)
                err = np.degrees(np.abs(mujoco_angles(m, v, ctrl, dt, every) - mref)).max()
                rows.append(("MuJoCo RK4", f"dt {dt:g}", err, 1e3 * mujoco_cpu(m, v, ctrl, args.repeat, n)))
            print(f"\nbelted analogue, {label}")
            print(f"  {'program':12s} {'setting':>12s} {'error (deg)':>12s} {'CPU (ms)':>9s}")
            for who, setting, err, ms in rows:
                print(f"  {who:12s} {setting:>12s} {err:12.3e} {ms:9.2f}")
            for who in ("hsri2d RK4", "hsri2d DP", "MuJoCo RK4"):
                ok = [r for r in rows if r[0] == who and r[2] <= 0.1]
                best = min(ok, key=lambda r: r[3]) if ok else None
                print(f"  cheapest within 0.1 deg, {who}: " +
                      (f"{best[1]}, {best[3]:.2f} ms" if best else "none of these settings"))


def what_happens(m, v, ctrl, lengths):
    """The belts' largest stretch past their slack and the contacts' largest count."""
    d = mujoco.MjData(m)
    d.qvel[:] = v
    stretch = np.zeros(m.ntendon)
    ncon = 0
    for k in range(N_STEP):
        if ctrl is not None:
            d.ctrl[0] = ctrl[k, 0]
        mujoco.mj_step(m, d)
        if m.ntendon:
            stretch = np.maximum(stretch, d.ten_length[:m.ntendon] - np.array(lengths))
        ncon = max(ncon, d.ncon)
    return stretch, ncon


def hsri2d_cpu(bench, decks, repeat):
    out = subprocess.run([bench, "--repeat", str(repeat), "--run-only", *decks], check=True,
                         capture_output=True, text=True).stdout
    ms = {}
    for line in out.splitlines():
        f = line.split()
        if f and f[0].endswith(".deck"):
            ms[f[0]] = float(f[2])
    return ms


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--repeat", type=int, default=11)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--bench", default=os.path.join(TOP, "build/release/hsri2d_bench"))
    ap.add_argument("--accuracy", action="store_true", help="time to accuracy on the belted analogue")
    args = ap.parse_args()
    if args.accuracy:
        accuracy(args)
        return
    ctrl = (VEHICLE_MASS * pulse(N_STEP)).reshape(N_STEP, 1)
    body = mujoco.MjModel.from_xml_string(mjcf(BODY_ALONE))
    belted, belted_len = belted_driver()
    smooth, smooth_len = belted_driver(friction=False)
    interior, interior_len = interior_driver()
    import tempfile
    work = tempfile.mkdtemp()
    smooth_path = os.path.join(work, "belted_driver_smooth.deck")
    with open(os.path.join(TOP, "decks/belted_driver.deck")) as f, open(smooth_path, "w") as g:
        g.write(smooth_deck(f.read()))
    cases = [("tools/bench/body_alone.deck", body, initial_velocity(body, BODY_ALONE), None, []),
             ("decks/belted_driver.deck", belted, initial_velocity(belted, BELTED, 528.0), ctrl, belted_len),
             (smooth_path, smooth, initial_velocity(smooth, BELTED, 528.0), ctrl, smooth_len),
             ("decks/default.deck", interior, initial_velocity(interior, INTERIOR, 528.0), ctrl, interior_len)]
    decks = [os.path.join(TOP, c[0]) for c in cases]     # (an absolute path stays itself)
    ours = {c[0]: [] for c in cases}
    theirs = {c[0]: [] for c in cases}
    for _ in range(args.rounds):
        ms = hsri2d_cpu(args.bench, decks, args.repeat)
        for name, m, v, u, _ in cases:
            ours[name].append(ms[os.path.basename(name)])
            theirs[name].append(1e3 * mujoco_cpu(m, v, u, args.repeat))
    print(f"MuJoCo {mujoco.__version__}; RK4, dt = {DT} s, {N_STEP} steps; CPU ms, medians of "
          f"{args.rounds} rounds of {args.repeat}")
    print(f"{'deck':32s} {'hsri2d':>8s} {'MuJoCo':>8s} {'ratio':>6s}  MuJoCo model: dof, belts, pairs; "
          "largest belt stretch (in), contacts")
    for name, m, v, u, lengths in cases:
        a, b = statistics.median(ours[name]), statistics.median(theirs[name])
        stretch, ncon = what_happens(m, v, u, lengths)
        shown = "belted, no joint friction/stops" if name == smooth_path else name
        print(f"{shown:32s} {a:8.2f} {b:8.2f} {b / a:6.2f}  {m.nv} dof, {m.ntendon} belts, {m.npair} pairs; "
              f"{' '.join(f'{s:.2f}' for s in stretch) or '-'}; up to {ncon}")


if __name__ == "__main__":
    main()
