#!/usr/bin/python3
"""Plots and the Markdown table of the benchmark campaign from the Planner Arena SQLite database written
by ompl_benchmark_statistics.

Usage: report.py DB OUTDIR [REFERENCE_CSV]
Writes OUTDIR/travel_time.png, OUTDIR/solve_time.png, OUTDIR/success_rate.png and OUTDIR/table.md, and prints the
table. Definitions (per problem and planner, over the runs of the campaign):
  success   = share of runs that returned an exact solution ending at the goal ("reached_goal")
  valid     = share of those whose path, re-flown from t0 along its x, y with the travel-time code, is valid
              ("plan_valid": every waypoint and leg inside the region / time window and free of forbidden regions)
  motions   = share of those whose motions as returned (with the planner's own time stamps) pass the motion validator
  median T  = median re-simulated travel time ("travel_time") over the valid runs
  / ZA*TVE  = median T divided by ZA*TVE's median T on the same problem
  optimum   = the problem's optimum (reference.csv: Zermelo shooting in open water, else the level-set front
              extrapolated from its two finest cells h and 2h, 2 T(h) - T(2h); with ice zones kept out of the front, an
              upper bound). OMPL's control planners (control_SST, control_RRT, control_KPIECE1: heading controls,
              GliderControl.h) reach a goal disc (their goal tolerance, reference.csv control_goal_tolerance), so their
              optimum is the front's first entry into that disc (reference_disc), extrapolated the same way
  / optimum = median T divided by that optimum
"""
import csv
import math
import os
import sqlite3
import statistics
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

LATTICE = ["TVE", "A*TVE", "ZTVE", "ZA*TVE", "Wavefront", "LevelSet", "Isochrone"]
PROBLEM_ORDER = ["open_water", "islands", "ice", "closure", "jet_v020", "jet_v015", "gyre"]
CONTROL_PREFIX = "control_"
# reference.csv columns: the current names, then those of earlier campaigns (cells 0.1 / 0.05 / 0.025)
LEVEL_SET_COLUMNS = [("level_set_coarse", "level_set_medium", "level_set_fine", "level_set_seconds_fine",
                      "ice_passable_fine"),
                     ("level_set_0.1", "level_set_0.05", "level_set_0.025", "level_set_seconds_0.025",
                      "ice_passable_0.025")]


def clean(name):
    return name.replace("geometric_", "")


def load(db):
    con = sqlite3.connect(db)
    con.row_factory = sqlite3.Row
    cols = [r[1] for r in con.execute("PRAGMA table_info(runs)")]

    def col(name):
        return name if name in cols else "NULL"

    q = ("SELECT experiments.problem AS problem, plannerConfigs.name AS planner, runs.time AS time, "
         "%s AS solved, %s AS reached, %s AS valid, %s AS motions, %s AS travel, %s AS cfc, %s AS cmc "
         "FROM runs JOIN experiments ON runs.experimentid = experiments.id "
         "JOIN plannerConfigs ON runs.plannerid = plannerConfigs.id" %
         (col("solved"), col("reached_goal"), col("plan_valid"), col("path_motions_valid"), col("travel_time"),
          col("CFC"), col("CMC")))
    data = {}
    for r in con.execute(q):
        data.setdefault(r["problem"], {}).setdefault(clean(r["planner"]), []).append(dict(r))
    return data


def median(xs):
    return statistics.median(xs) if xs else float("nan")


def fmt(v, digits=3):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "-"
    return ("%." + str(digits) + "f") % v


def main():
    db, out = sys.argv[1], sys.argv[2]
    refcsv = sys.argv[3] if len(sys.argv) > 3 else os.path.join(out, "reference.csv")
    ref, refdisc, refrows = {}, {}, {}
    if os.path.exists(refcsv):
        for row in csv.DictReader(open(refcsv)):
            refrows[row["problem"]] = row
            if row["found"] == "1":
                ref[row["problem"]] = float(row["reference_travel_time"])
            if row.get("reference_disc") not in (None, "", "nan", "inf"):
                refdisc[row["problem"]] = float(row["reference_disc"])

    def optimum(p, pl):
        """The optimum a planner's travel time is compared with (the goal disc for the control planners)."""
        if pl.startswith(CONTROL_PREFIX):
            return refdisc.get(p, float("nan"))
        return ref.get(p, float("nan"))
    data = load(db)
    problems = [p for p in PROBLEM_ORDER if p in data] + sorted(p for p in data if p not in PROBLEM_ORDER)
    planners = []
    for p in problems:
        for pl in data[p]:
            if pl not in planners:
                planners.append(pl)
    planners = [p for p in LATTICE if p in planners] + [p for p in planners if p not in LATTICE]

    stats = {}
    for p in problems:
        for pl in planners:
            runs = data[p].get(pl, [])
            n = len(runs)
            reached = [r for r in runs if r["reached"] == 1]
            valid = [r for r in reached if r["valid"] == 1]
            motions = [r for r in reached if r["motions"] == 1]
            T = [r["travel"] for r in valid if r["travel"] is not None]
            stats[(p, pl)] = dict(
                n=n, success=len(reached) / n if n else float("nan"),
                valid=len(valid) / len(reached) if reached else float("nan"),
                motions=len(motions) / len(reached) if reached else float("nan"),
                T=T, medT=median(T), time=[r["time"] for r in runs], medTime=median([r["time"] for r in runs]),
                medCFC=median([r["cfc"] for r in runs if r["cfc"] is not None]),
                medCMC=median([r["cmc"] for r in runs if r["cmc"] is not None]))

    lines = ["| problem | planner | runs | success | valid | motions valid | median travel time | / ZA*TVE | optimum "
             "| / optimum | median solve time (s) | median CFC | median CMC |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    verdicts = []
    for p in problems:
        z = stats.get((p, "ZA*TVE"), {}).get("medT", float("nan"))
        for pl in planners:
            s = stats[(p, pl)]
            if s["n"] == 0:
                continue
            rz = s["medT"] / z if z == z and s["medT"] == s["medT"] else float("nan")
            opt = optimum(p, pl)
            rr = s["medT"] / opt if opt == opt and s["medT"] == s["medT"] else float("nan")
            lines.append("| %s | %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
                p, pl, s["n"], fmt(100 * s["success"], 0) + "%", fmt(100 * s["valid"], 0) + "%"
                if s["valid"] == s["valid"] else "-", fmt(100 * s["motions"], 0) + "%"
                if s["motions"] == s["motions"] else "-", fmt(s["medT"]), fmt(rz), fmt(opt), fmt(rr),
                fmt(s["medTime"], 3), fmt(s["medCFC"], 0), fmt(s["medCMC"], 0)))
        # the figures: ZA*TVE no worse than any sampling planner, 100% valid where a solution exists
        zs = stats.get((p, "ZA*TVE"))
        if zs and z != z:  # no ZA*TVE path (strong currents): who reached the goal, and how close to the optimum
            best = ["%s %s (%s)" % (pl, fmt(stats[(p, pl)]["medT"]), fmt(100 * stats[(p, pl)]["success"], 0) + "%")
                    for pl in planners if stats[(p, pl)]["n"] and stats[(p, pl)]["medT"] == stats[(p, pl)]["medT"]]
            verdicts.append("- %s: ZA*TVE found no path; median travel times (solved share): %s" % (
                p, ", ".join(best) if best else "none"))
        elif zs:
            worse = [pl for pl in planners if pl not in LATTICE and stats[(p, pl)]["medT"] == stats[(p, pl)]["medT"]
                     and stats[(p, pl)]["medT"] < z]
            verdicts.append("- %s: ZA*TVE median %s, valid %s; sampling planners with a lower median: %s" % (
                p, fmt(z), fmt(100 * zs["valid"], 0) + "%" if zs["valid"] == zs["valid"] else "-",
                ", ".join(worse) if worse else "none"))
    if ref:
        verdicts.append("- optimum per problem: " + ", ".join(
            "%s %s (%s)" % (k, fmt(v, 4), refrows[k].get("method", "shooting")) for k, v in ref.items()))
    for k, row in refrows.items():
        names = next((c for c in LEVEL_SET_COLUMNS if c[2] in row), None)
        if names:
            coarse, medium, fine, seconds, passable = names
            extra = ""
            if row.get(passable) not in (None, "", "nan"):
                extra = "; ice passable (lower bound) %s" % fmt(float(row[passable]), 4)
            if k in refdisc and any(pl.startswith(CONTROL_PREFIX) for pl in data.get(k, {})):
                extra += "; first entry into the control goal disc (radius %s) %s" % (
                    fmt(float(row["control_goal_tolerance"]), 4), fmt(refdisc[k], 4))
            verdicts.append("- level-set resolution study, %s: cell %s: %s / %s / %s, extrapolated %s "
                            "(%s s at the finest)%s"
                            % (k, row.get("cells", "0.1 / 0.05 / 0.025"), fmt(float(row[coarse]), 4),
                               fmt(float(row[medium]), 4), fmt(float(row[fine]), 4),
                               fmt(float(row["level_set_extrapolated"]), 4), fmt(float(row[seconds]), 1), extra))
    text = "\n".join(lines) + "\n\n" + "\n".join(verdicts) + "\n"
    open(os.path.join(out, "table.md"), "w").write(text)
    print(text)

    # plots: one panel per problem, planners on the x axis
    def panel_figure(fname, ylabel, getter, kind):
        fig, axes = plt.subplots(1, len(problems), figsize=(4.2 * len(problems), 4.5), squeeze=False)
        for ax, p in zip(axes[0], problems):
            pls = [pl for pl in planners if stats[(p, pl)]["n"] > 0]
            if kind == "box":
                vals = [getter(stats[(p, pl)]) for pl in pls]
                ax.boxplot([v if v else [float("nan")] for v in vals], labels=pls)
                if kind == "box" and fname.startswith("travel") and p in ref:
                    ax.axhline(ref[p], color="g", ls="--", lw=1, label="optimum %.3f" % ref[p])
                    if p in refdisc and any(pl.startswith(CONTROL_PREFIX) for pl in pls):
                        ax.axhline(refdisc[p], color="m", ls=":", lw=1, label="goal disc %.3f" % refdisc[p])
                    ax.legend(fontsize=7)
            else:
                vals = [getter(stats[(p, pl)]) for pl in pls]
                ax.bar(range(len(pls)), [100 * v if v == v else 0 for v in vals],
                       color=["tab:red" if pl in LATTICE else "tab:green" if pl.startswith(CONTROL_PREFIX)
                              else "tab:blue" for pl in pls])
                ax.set_xticks(range(len(pls)))
                ax.set_xticklabels(pls)
                ax.set_ylim(0, 105)
            ax.set_title(p)
            ax.set_ylabel(ylabel)
            ax.tick_params(axis="x", rotation=60, labelsize=8)
            if fname.startswith("solve"):
                ax.set_yscale("log")
        fig.tight_layout()
        fig.savefig(os.path.join(out, fname), dpi=90)
        plt.close(fig)

    panel_figure("travel_time.png", "re-simulated travel time (valid runs)", lambda s: s["T"], "box")
    panel_figure("solve_time.png", "solve time (s)", lambda s: s["time"], "box")
    panel_figure("success_rate.png", "success rate (%)", lambda s: s["success"], "bar")


if __name__ == "__main__":
    main()
