#!/usr/bin/env python3
"""Compares the outputs of one process with those of an MPI job (tests/mpi/run_mpi_test.sh).

Usage: compare_runs.py plan DIR_ONE DIR_MPI       every file byte for byte, but summary.json: every value equal
                                                  except the wall times, the threads and (ensembles) the current-model
                                                  calls, which count calls on fields shared by threads
       compare_runs.py campaign DIR_ONE DIR_MPI   every OMPL log: the same experiments, planners, run properties and
                                                  values per run, except the timing columns (time, memory)
Exit 0 when they agree, 1 with the differences printed.
"""
import json
import os
import sys

IGNORED_JSON = {"wall_time_s", "threads", "current_model_calls", "processes"}
TIMING = ("time REAL", "memory REAL")


def strip(value):
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if k not in IGNORED_JSON}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value


def compare_plan(one, mpi):
    bad = []

    def files(root):  # every file, in folders too (a fleet's gliders)
        return sorted(os.path.relpath(os.path.join(d, f), root) for d, _, fs in os.walk(root) for f in fs)

    names = files(one)
    if files(mpi) != names:
        return [f"files differ: {names} vs {files(mpi)}"]
    for name in names:
        a, b = os.path.join(one, name), os.path.join(mpi, name)
        if name.endswith(".json"):
            if strip(json.load(open(a))) != strip(json.load(open(b))):
                bad.append(f"{name}: values differ")
        elif open(a, "rb").read() != open(b, "rb").read():
            bad.append(f"{name}: bytes differ")
    return bad


def read_log(path):
    """{experiment: {planner: [run dicts]}} and the experiment properties of an OMPL benchmark log."""
    lines = open(path).read().split("\n")
    out, i = {}, 0
    experiment = [l for l in lines if l.startswith("Experiment ")][0]
    while i < len(lines) and not lines[i].endswith(" planners"):
        i += 1
    count = int(lines[i].split()[0])
    i += 1
    for _ in range(count):
        planner = lines[i]
        i += 1
        ncommon = int(lines[i].split()[0])
        i += 1 + ncommon
        nprops = int(lines[i].split()[0])
        props = lines[i + 1:i + 1 + nprops]
        i += 1 + nprops
        nruns = int(lines[i].split()[0])
        runs = []
        for r in lines[i + 1:i + 1 + nruns]:
            values = [v.strip() for v in r.split(";")][:nprops]
            runs.append({p: v for p, v in zip(props, values) if p not in TIMING})
        i += 1 + nruns
        while lines[i] != ".":
            i += 1
        i += 1
        out[planner] = runs
    return experiment, out


def compare_campaign(one, mpi):
    logs = sorted(n for n in os.listdir(one) if n.endswith(".log"))
    if not logs or sorted(n for n in os.listdir(mpi) if n.endswith(".log")) != logs:
        return [f"logs differ: {logs} vs {sorted(os.listdir(mpi))}"]
    bad = []
    for name in logs:
        a, b = read_log(os.path.join(one, name)), read_log(os.path.join(mpi, name))
        if a != b:
            bad.append(f"{name}: runs differ\n  one: {a}\n  mpi: {b}")
    return bad


if __name__ == "__main__":
    mode, one, mpi = sys.argv[1:4]
    problems = compare_plan(one, mpi) if mode == "plan" else compare_campaign(one, mpi)
    for p in problems:
        print(p)
    sys.exit(1 if problems else 0)
