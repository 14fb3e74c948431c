"""Shared fixtures of the Python module's tests (run by ctest: PYTHONPATH holds the build tree's package,
GLIDER_PLAN the command line, OMPL_GLIDER_SOURCE_DIR the sources)."""
import json
import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("OMPL_GLIDER_SOURCE_DIR",
                            os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
EXAMPLES = os.path.join(SOURCE_DIR, "examples")


def glider_plan(*args, out_dir=None):
    """Runs glider_plan; returns (exit status, stdout, stderr, summary.json as a dict or None)."""
    exe = os.environ.get("GLIDER_PLAN")
    if not exe:
        pytest.skip("GLIDER_PLAN (the glider_plan binary) is not set")
    cmd = [exe, *args] + (["--out", str(out_dir)] if out_dir else [])
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    summary = None
    if out_dir and os.path.exists(os.path.join(out_dir, "summary.json")):
        with open(os.path.join(out_dir, "summary.json")) as f:
            summary = json.load(f)
    return p.returncode, p.stdout, p.stderr, summary
