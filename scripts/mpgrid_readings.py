#!/usr/bin/env python3
"""Alternative readings of the MP-Grid memory example (docs/mp_grid.md,
"Session 10"): per-pixel bounds and near/far planes, each against the
paper's 6,198,605 bytes.  A prototype kept so that those numbers can be
regenerated; fragsim itself implements only the bounding-box rule
(`build/fragsim mpgrid`).  Needs python3-numpy (not a build dependency):
    apt-get install python3-numpy && python3 scripts/mpgrid_readings.py
"""
import numpy as np

PAPER = 6198605
N, FOV = 1024, 45.0
EYE, CTR, UP = np.array([0, 0, 1000.]), np.array([2500, 2500, 0.]), np.array([0, 0, 1.])


def pyr(r):
    return (4 * r * r - 1) // 3 if r else 0


def up2(x):
    r = 1
    while r < x * (1 - 1e-9) and r < 1024:
        r *= 2
    return r


def report(name, tab):
    tot = sum(pyr(r) for r in tab.values())
    print(f"{name:34s} {tot:9d} {100 * (tot - PAPER) / PAPER:+7.2f}%  empty {sum(r == 0 for r in tab.values())}")


def per_pixel():
    f = CTR - EYE; f /= np.linalg.norm(f)
    s = np.cross(f, UP); s /= np.linalg.norm(s)
    u = np.cross(s, f)
    t = np.tan(np.radians(FOV) / 2)

    def hit(px, py):
        d = f + (px / (N / 2) - 1)[..., None] * t * s + (py / (N / 2) - 1)[..., None] * t * u
        ok = d[..., 2] < 0
        lam = np.where(ok, -EYE[2] / np.where(ok, d[..., 2], -1), np.nan)
        return EYE[0] + lam * d[..., 0], EYE[1] + lam * d[..., 1], ok

    p = np.arange(N) + 0.5
    PX, PY = np.meshgrid(p, p)
    gx, gy, ok = hit(PX, PY)
    h, sc = 1e-3, 1.024  # texels per metre
    ax, ay, _ = hit(PX + h, PY)
    bx, by, _ = hit(PX, PY + h)
    ux, vx, uy, vy = (ax - gx) / h * sc, (ay - gy) / h * sc, (bx - gx) / h * sc, (by - gy) / h * sc
    with np.errstate(invalid="ignore"):
        i = np.where(ok, np.floor(gx / 1000), -1).astype(int)
        j = np.where(ok, np.floor(gy / 1000), -1).astype(int)
    ok &= (i >= 0) & (i < 5) & (j >= 0) & (j < 5)
    rhos = {
        "per pixel, GL rho (larger side)": np.maximum(np.hypot(ux, vx), np.hypot(uy, vy)),
        "per pixel, largest component": np.maximum.reduce([abs(ux), abs(vx), abs(uy), abs(vy)]),
        "per pixel, footprint box, larger": np.maximum(abs(ux) + abs(uy), abs(vx) + abs(vy)),
        "per pixel, footprint box, smaller": np.minimum(abs(ux) + abs(uy), abs(vx) + abs(vy)),
    }
    for name, rho in rhos.items():
        tab = {}
        for a in range(5):
            for b in range(5):
                m = ok & (i == a) & (j == b)
                tab[(a, b)] = up2(1024 / np.min(rho[m])) if m.any() else 0
        report(name, tab)


def clipped(znear, zfar):
    f = CTR - EYE; f /= np.linalg.norm(f)
    s = np.cross(f, UP); s /= np.linalg.norm(s)
    u = np.cross(s, f)
    V = np.eye(4); V[0, :3], V[1, :3], V[2, :3] = s, u, -f
    V[:3, 3] = -V[:3, :3] @ EYE
    c = 1 / np.tan(np.radians(FOV) / 2)
    P = np.zeros((4, 4)); P[0, 0] = P[1, 1] = c; P[3, 2] = -1
    P[2, 2] = (zfar + znear) / (znear - zfar); P[2, 3] = 2 * zfar * znear / (znear - zfar)
    M = P @ V
    tab = {}
    for a in range(5):
        for b in range(5):
            x0, y0 = a * 1000, b * 1000
            poly = [M @ np.array([x, y, 0, 1.]) for x, y in
                    ((x0, y0), (x0 + 1000, y0), (x0 + 1000, y0 + 1000), (x0, y0 + 1000))]
            for k in range(3):  # Sutherland-Hodgman against the six clip planes
                for sg in (1, -1):
                    out = []
                    for q in range(len(poly)):
                        A, B = poly[q], poly[(q + 1) % len(poly)]
                        da, db = A[3] - sg * A[k], B[3] - sg * B[k]
                        if da >= 0: out.append(A)
                        if (da >= 0) != (db >= 0): out.append(A + (B - A) * (da / (da - db)))
                    poly = out
            if not poly:
                tab[(a, b)] = 0
                continue
            W = np.array([[(q[0] / q[3] + 1) * N / 2, (q[1] / q[3] + 1) * N / 2] for q in poly])
            tab[(a, b)] = up2((W.max(0) - W.min(0)).max())
    report(f"box rule, near {znear:g} m, far {zfar:g} m", tab)


per_pixel()
for zn, zf in ((1, 1e5), (1500, 1e5), (1, 6000), (1, 5000)):
    clipped(zn, zf)
