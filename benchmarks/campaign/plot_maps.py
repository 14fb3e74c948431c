#!/usr/bin/python3
"""Map figure of the campaign problems: current speed of the meandering jet at t0 ([EichhornRAS] Eq. 7-9), forbidden
regions, and the ZA*TVE and RRT* paths written by glider_campaign_paths (OUTDIR/maps.json).
Usage: plot_maps.py OUTDIR  ->  OUTDIR/maps.png"""
import json
import math
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def jet_speed(x, y, t, B0=1.2, eps=0.3, om=0.4, th=math.pi / 2, k=0.84, c=0.12):
    """|u, v| of the meandering jet by central differences of the stream function ([EichhornRAS] Eq. 7-9)."""
    def phi(x, y):
        B = B0 + eps * np.cos(om * t + th)
        s = np.sin(k * (x - c * t))
        return 1 - np.tanh((y - B * np.cos(k * (x - c * t))) / np.sqrt(1 + k * k * B * B * s * s))
    h = 1e-4
    u = -(phi(x, y + h) - phi(x, y - h)) / (2 * h)
    v = (phi(x + h, y) - phi(x - h, y)) / (2 * h)
    return np.hypot(u, v)


def main():
    out = sys.argv[1]
    data = json.load(open(out + "/maps.json"))
    names = list(data.keys())
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    X, Y = np.meshgrid(np.linspace(0, 10, 201), np.linspace(-4, 4, 161))
    S = jet_speed(X, Y, 0.0)
    for ax, name in zip(axes.flat, names):
        d = data[name]
        ax.contourf(X, Y, S, levels=20, cmap="Blues", alpha=0.6)
        for r in d["regions"]:
            P = np.array(r["outer"] + [r["outer"][0]])
            if r["kind"] == "ice zone":
                for (t, dx, dy) in r["drift"][::2]:
                    ax.plot(P[:, 0] + dx, P[:, 1] + dy, color="c", lw=0.8, alpha=0.3 + 0.7 * (t == 0))
                ax.text(P[0, 0], P[0, 1], "%s (t=0, max %.2g under)" % (r["name"], r["limit"]), fontsize=7)
            elif "windows" in r:
                ax.fill(P[:, 0], P[:, 1], color="orange", alpha=0.4)
                ax.text(P[0, 0], P[0, 1] + 0.1, "%s closed %s" % (r["name"], r["windows"]), fontsize=7)
            else:
                ax.fill(P[:, 0], P[:, 1], color="saddlebrown", alpha=0.8)
                ax.text(np.mean(P[:, 0]), np.mean(P[:, 1]), r["name"], color="w", fontsize=8)
        for pname, style in (("ZA*TVE", "r.-"), ("RRTstar", "g.--")):
            if pname in d["paths"]:
                p = np.array(d["paths"][pname]["states"])
                ax.plot(p[:, 0], p[:, 1], style, lw=1.2, ms=3,
                        label="%s: T=%s%s" % (pname, "%.3f" % d["paths"][pname]["travel_time"]
                                               if d["paths"][pname]["travel_time"] is not None else "inf",
                                                "" if d["paths"][pname]["valid"] else " (invalid)"))
        ax.plot(*d["start"], "ko")
        ax.plot(*d["goal"], "k*", ms=10)
        ax.set_title(name)
        ax.set_xlim(0, 10)
        ax.set_ylim(-4, 4)
        ax.set_aspect("equal")
        ax.legend(fontsize=7, loc="lower right")
    fig.suptitle("Campaign problems on the meandering jet (shading: current speed at t0; paths: re-simulated T)")
    fig.tight_layout()
    fig.savefig(out + "/maps.png", dpi=90)


if __name__ == "__main__":
    main()
