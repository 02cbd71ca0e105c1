#!/usr/bin/env python3
"""Writes content/gestures/handlike.json: labelled strokes that test the
gesture recognizer on data its training generator did not make.

These are synthetic "hand-like" strokes, not strokes recorded from a person
(docs/gestures.md says so). They differ from garden/gesture/stroke_generator
on purpose, in everything but the labels' definitions: shapes are
centripetal Catmull-Rom splines through control points of other
proportions, timed by a minimum-jerk speed profile between control points
(slow at corners, as a hand is) and sampled at 60 Hz, with correlated
tremor, mostly upright on the screen, rounded to whole pixels as a mouse
reports them. Standard library only; the same file every run (fixed seed,
our own Box-Muller instead of random.gauss).

    python3 scripts/make-handlike-gestures.py [OUTPUT]
"""
import json
import math
import random
import sys

SEED = 2024
PER_GESTURE = 40
NONE = 200
R = random.Random(SEED)


def gauss():
    u1, u2 = 1.0 - R.random(), R.random()
    return math.sqrt(-2.0 * math.log(u1)) * math.cos(2.0 * math.pi * u2)


def catmull_rom(points, per_segment=24):
    """Centripetal Catmull-Rom through `points` (ends doubled)."""
    p = [points[0]] + points + [points[-1]]
    out = [points[0]]
    for i in range(1, len(p) - 2):
        p0, p1, p2, p3 = p[i - 1], p[i], p[i + 1], p[i + 2]

        def knot(a, b):
            return max(math.dist(a, b) ** 0.5, 1e-6)
        t1 = knot(p0, p1)
        t2 = t1 + knot(p1, p2)
        t3 = t2 + knot(p2, p3)
        for k in range(1, per_segment + 1):
            t = t1 + (t2 - t1) * k / per_segment

            def lerp(a, b, ta, tb):
                w = (t - ta) / (tb - ta)
                return (a[0] + (b[0] - a[0]) * w, a[1] + (b[1] - a[1]) * w)
            a1 = lerp(p0, p1, 0.0, t1)
            a2 = lerp(p1, p2, t1, t2)
            a3 = lerp(p2, p3, t2, t3)
            b1 = lerp(a1, a2, 0.0, t2)
            b2 = lerp(a2, a3, t1, t3)
            out.append(lerp(b1, b2, t1, t2))
    return out


def corner_path(controls, roundness):
    """A polyline through `controls` whose corners are cut by a spline of
    `roundness` (a fraction of the shorter neighbouring side): hands round
    corners a little."""
    pts = [controls[0]]
    for i in range(1, len(controls) - 1):
        a, b, c = controls[i - 1], controls[i], controls[i + 1]
        r = roundness * min(math.dist(a, b), math.dist(b, c))
        da, dc = math.dist(a, b), math.dist(b, c)
        pts.append((b[0] + (a[0] - b[0]) * r / da, b[1] + (a[1] - b[1]) * r / da))
        pts.append(b)
        pts.append((b[0] + (c[0] - b[0]) * r / dc, b[1] + (c[1] - b[1]) * r / dc))
    pts.append(controls[-1])
    return catmull_rom(pts, 8)


def jitter(v, amount):
    return (v[0] + amount * (R.random() - 0.5), v[1] + amount * (R.random() - 0.5))


# --- shapes, in a unit box, y down ----------------------------------------

def v_shape():
    depth = R.uniform(0.7, 1.3)
    apex = R.uniform(0.3, 0.7)
    width = R.uniform(0.5, 1.1)
    c = [(0.0, 0.0), (apex * width, depth), (width, R.uniform(-0.2, 0.3))]
    if R.random() < 0.25:  # a check mark: short first arm
        c = [(0.0, 0.5 * depth), (apex * width * 0.5, depth), (width, -0.2)]
    c = [jitter(p, 0.08) for p in c]
    if R.random() < 0.5:
        c.reverse()  # right to left: a sharp turn the other way, still a V
    return corner_path(c, R.uniform(0.0, 0.12))


def u_shape():
    """A U from its left tip (a left half turn); an arch is this mirrored."""
    w = R.uniform(0.5, 1.2)
    h = R.uniform(0.4, 1.3)
    kind = R.random()
    if kind < 0.5:  # round
        c = [(0.0, 0.0), (0.02 * w, 0.55 * h), (0.5 * w, h), (0.98 * w, 0.55 * h), (w, R.uniform(-0.1, 0.2) * h)]
        c = [jitter(p, 0.06) for p in c]
        return catmull_rom(c)
    if kind < 0.8:  # squared
        c = [(0.0, 0.0), (0.0, h), (w, h), (w, R.uniform(0.0, 0.3) * h)]
        return corner_path([jitter(p, 0.05) for p in c], R.uniform(0.15, 0.4))
    # lopsided: one arm much longer
    c = [(0.0, -0.6 * h), (0.05 * w, 0.6 * h), (0.45 * w, h), (0.95 * w, 0.7 * h), (w, 0.35 * h)]
    return catmull_rom([jitter(p, 0.06) for p in c])


def z_shape():
    w = R.uniform(0.6, 1.2)
    h = R.uniform(0.6, 1.3)
    c = [(0.0, 0.0), (w, 0.0), (R.uniform(0.0, 0.15) * w, h), (w * R.uniform(0.9, 1.15), h)]
    if R.random() < 0.3:  # an N: the same turns, standing up
        c = [(0.0, h), (0.0, 0.0), (w, h), (w, 0.0)]
    c = [jitter(p, 0.07) for p in c]
    if R.random() < 0.3:
        c = [(-x, y) for x, y in c]  # mirrored: left then right, still alternating
    return corner_path(c, R.uniform(0.0, 0.12))


def loop_shape(clockwise):
    turns = R.uniform(1.0, 3.2)
    n = int(turns * 10)
    start = R.uniform(0.0, 2 * math.pi)
    rx, ry = 0.5, 0.5 * R.uniform(0.6, 1.0)
    drift = (R.uniform(-0.15, 0.15), R.uniform(-0.15, 0.15))
    c = []
    for i in range(n + 1):
        u = i / n * turns
        t = start + (1 if clockwise else -1) * 2 * math.pi * u
        wob = 1.0 + 0.08 * gauss()
        c.append((rx * wob * math.cos(t) + drift[0] * u, ry * wob * math.sin(t) + drift[1] * u))
    return catmull_rom(c, 12)


def turning(pts):
    total = absolute = 0.0
    for a, b, c in zip(pts, pts[1:], pts[2:]):
        ax, ay, bx, by = b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]
        if ax * ax + ay * ay < 1e-12 or bx * bx + by * by < 1e-12:
            continue
        t = math.atan2(ax * by - ay * bx, ax * bx + ay * by)
        total += t
        absolute += abs(t)
    return math.degrees(total), math.degrees(absolute)


def no_gesture():
    kind = R.random()
    if kind < 0.3:  # straight line, any direction
        return catmull_rom([(0.0, 0.0), (0.5, 0.01 * gauss()), (1.0, 0.0)])
    if kind < 0.45:  # gentle arc or slightly curved line
        bend = R.uniform(-0.25, 0.25)
        return catmull_rom([(0.0, 0.0), (0.5, bend), (1.0, 0.0)])
    if kind < 0.6:  # a wave
        n = R.randint(3, 6)
        amp = R.uniform(0.04, 0.15)
        return catmull_rom([(i / n, amp * (1 if i % 2 else -1)) for i in range(n + 1)])
    # a scribble: crossing out, or a random walk of control points; refused
    # when it turns mostly one way (it would be a U, an arch or a loop) or
    # turns less than one and a half turns in all (a spline through a few
    # random points can be a clean V or Z, which is no scribble)
    while True:
        if R.random() < 0.5:
            n = R.randint(5, 9)
            c = [(R.uniform(0.0, 0.3) + (i % 2) * 0.7, i / n + 0.1 * gauss()) for i in range(n)]
        else:
            n = R.randint(6, 10)
            c = [(R.random(), R.random()) for _ in range(n)]
        pts = catmull_rom(c)
        total, absolute = turning(pts)
        if absolute > max(540.0, 1.6 * abs(total) + 90.0):
            return pts


def mirrored(pts):
    return [(-x, y) for x, y in pts]


SHAPES = {
    "sketch": v_shape,
    "union": u_shape,
    "intersect": lambda: mirrored(u_shape()) if R.random() < 0.8 else
    u_shape()[::-1],  # an arch, or a U drawn from its right tip
    "deform": z_shape,
    "shrink": lambda: loop_shape(True),
    "grow": lambda: loop_shape(False),
}


# --- the hand: timing, tremor, placement ----------------------------------

def arc_lengths(pts):
    s = [0.0]
    for a, b in zip(pts, pts[1:]):
        s.append(s[-1] + math.dist(a, b))
    return s


def at_length(pts, s, target):
    lo, hi = 0, len(s) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if s[mid] < target:
            lo = mid
        else:
            hi = mid
    seg = s[hi] - s[lo]
    w = 0.0 if seg <= 0 else (target - s[lo]) / seg
    return (pts[lo][0] + (pts[hi][0] - pts[lo][0]) * w, pts[lo][1] + (pts[hi][1] - pts[lo][1]) * w)


def curvature_speed(pts):
    """Relative speed along the path: slower where it bends (the two-thirds
    power law of hand movement), from the spline's own points."""
    speed = [1.0]
    for a, b, c in zip(pts, pts[1:], pts[2:]):
        ax, ay, bx, by = b[0] - a[0], b[1] - a[1], c[0] - b[0], c[1] - b[1]
        la, lb = math.hypot(ax, ay), math.hypot(bx, by)
        if la < 1e-12 or lb < 1e-12:
            speed.append(speed[-1])
            continue
        k = abs(math.atan2(ax * by - ay * bx, ax * bx + ay * by)) / (0.5 * (la + lb))
        speed.append(1.0 / (1.0 + 0.15 * k) ** (1.0 / 3.0))
    speed.append(1.0)
    return speed


def hand_sample(pts, size):
    s = arc_lengths(pts)
    speed = curvature_speed(pts)
    # Time to cover each piece, with a minimum-jerk start and stop.
    times = [0.0]
    for i in range(1, len(pts)):
        times.append(times[-1] + (s[i] - s[i - 1]) / max(speed[i], 0.05))
    duration = R.uniform(0.35, 1.4) * (1.0 + 0.2 * math.log(1.0 + s[-1]))
    frames = max(8, int(duration * 60.0))
    samples = []
    for f in range(frames + 1):
        tau = f / frames
        progress = 10 * tau ** 3 - 15 * tau ** 4 + 6 * tau ** 5  # minimum jerk
        target_time = progress * times[-1]
        lo = max(0, min(len(times) - 2, next((i for i, t in enumerate(times) if t >= target_time), len(times) - 1) - 1))
        seg = times[lo + 1] - times[lo]
        w = 0.0 if seg <= 0 else (target_time - times[lo]) / seg
        samples.append(at_length(pts, s, s[lo] + (s[lo + 1] - s[lo]) * min(1.0, max(0.0, w))))
    # Correlated tremor, in pixels: a smoothed random walk plus a 9 Hz shake.
    amount = R.uniform(0.3, 1.5) / size
    tx = ty = 0.0
    shake = R.uniform(0.0, 0.6) / size
    phase = R.uniform(0.0, 2 * math.pi)
    out = []
    for f, (x, y) in enumerate(samples):
        tx = 0.8 * tx + amount * gauss()
        ty = 0.8 * ty + amount * gauss()
        z = shake * math.sin(2 * math.pi * 9.0 * f / 60.0 + phase)
        out.append((x + tx + z, y + ty - z))
    return out


def place(pts, size):
    angle = math.radians(R.uniform(-25.0, 25.0)) if R.random() < 0.8 else R.uniform(0.0, 2 * math.pi)
    ca, sa = math.cos(angle), math.sin(angle)
    pts = [(x * ca - y * sa, x * sa + y * ca) for x, y in pts]
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    k = size / max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    ox, oy = R.uniform(100.0, 1500.0), R.uniform(100.0, 700.0)
    out = []
    for x, y in pts:
        q = [round(ox + (x - min(xs)) * k), round(oy + (y - min(ys)) * k)]
        if not out or q != out[-1]:  # a mouse reports moves only
            out.append(q)
    return out


def stroke(shape):
    size = R.uniform(60.0, 420.0)
    pts = shape()
    return place(hand_sample(pts, size), size)


def main():
    output = sys.argv[1] if len(sys.argv) > 1 else "content/gestures/handlike.json"
    strokes = []
    for label in ["sketch", "union", "intersect", "deform", "shrink", "grow"]:
        for _ in range(PER_GESTURE):
            strokes.append((label, stroke(SHAPES[label])))
    for _ in range(NONE):
        strokes.append(("none", stroke(no_gesture)))
    lines = ['{"about": "Synthetic hand-like strokes (not recorded from a person), made by '
             'scripts/make-handlike-gestures.py, never trained on: docs/gestures.md.",',
             ' "strokes": [']
    for i, (label, pts) in enumerate(strokes):
        text = json.dumps({"label": label, "points": pts}, separators=(",", ":"))
        lines.append("  " + text + ("," if i + 1 < len(strokes) else ""))
    lines.append(" ]}")
    with open(output, "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"wrote {len(strokes)} strokes to {output}")


if __name__ == "__main__":
    main()
