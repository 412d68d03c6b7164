"""What the Python module's tests share: the module itself and the built `metalfit` CLI to compare it with.

ctest (python.module) sets PYTHONPATH to the built module's folder and METALFIT_EXE to the CLI built beside it; both
use the same database (the source tree's data/, or $METALFIT_DATA) and OCIO is unset (metalfit's own config).
"""
import json
import os
import subprocess

import pytest

import metalfit

EXE = os.environ.get("METALFIT_EXE", "metalfit")


def run_cli(*args, check=True):
    """Runs the metalfit CLI; returns the CompletedProcess (text)."""
    process = subprocess.run([EXE, *args], capture_output=True, text=True, check=False)
    if check and process.returncode != 0:
        raise AssertionError(f"metalfit {' '.join(args)}: exit {process.returncode}: {process.stderr}")
    return process


def cli_json(*args):
    return json.loads(run_cli(*args).stdout)


def cli_error(*args):
    """The CLI's exit code and its one-line message, without the "metalfit: " prefix."""
    process = run_cli(*args, check=False)
    lines = [line for line in process.stderr.splitlines() if not line.startswith("metalfit: warning:")]
    assert process.returncode != 0 and len(lines) == 1, process.stderr
    assert lines[0].startswith("metalfit: ")
    return process.returncode, lines[0][len("metalfit: "):]


@pytest.fixture(scope="session")
def gold_fit():
    """The module's fit of gold with two models, and the CLI's record of the same request."""
    models = ["f82-tint", "schlick"]
    return (metalfit.fit("gold", models=models, jobs=1),
            cli_json("fit", "gold", "--model", ",".join(models), "--json", "-j", "1"))
