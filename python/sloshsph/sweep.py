"""Sweeps: one run per frequency ratio and per value of any swept key, in parallel processes, laid
out exactly as ``sloshsph sweep`` lays them out (so ``sloshsph report DIR`` reads them)."""

import csv
import json
import os
import signal
import subprocess
import sys
import time as _time

import numpy as np

from . import _core, _toml
from .case import as_case
from .errors import Interrupted, RunFailed
from .runs import Run


class Sweep:
    """A sweep directory.

    Attributes:
        path: the directory.
        table: frequency_response.csv as a dict {column: array} (numbers as float64, ``status``
            and ``run_dir`` as str arrays), rows in the order of the points.
        points: the points' ``Run`` objects, in the same order.
        failed: labels of the points that did not complete.
    """

    def __init__(self, path, points):
        self.path = os.fspath(path)
        self.points = [Run(p["directory"]) if os.path.isdir(p["directory"]) else None for p in points]
        self.labels = [p["label"] for p in points]
        self.table = read_frequency_response(os.path.join(self.path, "frequency_response.csv"))
        self.failed = [label for label, status in zip(self.labels, self.table.get("status", [])) if status != "completed"]

    def __repr__(self):
        return f"<sloshsph.Sweep {self.path!r}: {len(self.labels)} points, {len(self.failed)} not completed>"


def read_frequency_response(path):
    """A frequency_response.csv (or any CSV with a header row) as a dict of columns: a column whose
    every entry is a number becomes a float64 array, any other a str array."""
    with open(os.fspath(path), newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        return {}
    names, body = rows[0], rows[1:]
    table = {}
    for k, name in enumerate(names):
        texts = [r[k] if k < len(r) else "" for r in body]
        try:
            table[name] = np.array([float(t) for t in texts], dtype=float)
        except ValueError:
            table[name] = np.array(texts, dtype=str)
    return table


def _axes_and_fixed(case, sets):
    """The case's overrides plus the scalar ``sets``, and the swept keys (list values)."""
    fixed = case.overrides
    axes = []
    for key, value in (sets or {}).items():
        if isinstance(value, (list, tuple)) or (hasattr(value, "ndim") and getattr(value, "ndim", 0) == 1):
            values = [_toml.value(v) for v in value]
            if not values:
                raise ValueError(f"sets[{key!r}] is an empty list: nothing to sweep")
            axes.append((key, values))
        else:
            fixed.append(f"{key}={_toml.value(value)}")
    return fixed, axes


def _betas(beta):
    if beta is None:
        return []
    if isinstance(beta, str):
        return _core.parse_beta_range(beta, "beta")
    values = [float(b) for b in np.atleast_1d(beta)]
    if not values or any(not b > 0 for b in values):
        raise ValueError(f"beta must hold positive frequency ratios, not {beta!r}")
    return values


def _already_done(case, fixed, point, retry_failed):
    """As ``sloshsph sweep`` decides: finished from the same resolved case (CaseError for another's)."""
    return _core.point_finished(point, bool(retry_failed),
                                lambda: _core.check_case(case._text, case.source, case.name, fixed + point["overrides"])[1])


def _start(case, fixed, point, threads):
    """One point in its own Python process (sloshsph._point), its output in DIR/<label>.log."""
    resume = _core.point_resumable(point)
    job = {"text": case._text,  # str: a text that is not UTF-8 fails plan_sweep before any point starts
           "source": case.source, "name": case.name, "overrides": fixed + point["overrides"],
           "directory": point["directory"], "threads": threads, "force": os.path.exists(point["directory"]),
           "resume": resume}
    env = dict(os.environ)
    package_parent = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    env["PYTHONPATH"] = package_parent + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    log = open(point["directory"] + ".log", "ab")
    try:
        child = subprocess.Popen([sys.executable, "-m", "sloshsph._point"], stdin=subprocess.PIPE, stdout=log,
                                 stderr=subprocess.STDOUT, env=env)
        child.stdin.write(json.dumps(job).encode("utf-8"))
        child.stdin.close()
    finally:
        log.close()
    return child


def sweep(case, beta=None, sets=None, *, out=None, jobs=1, threads=None, retry_failed=False, progress=True,
          check=True):
    """Runs one simulation per frequency ratio ``beta`` and per combination of the swept keys, ``jobs``
    processes at a time, and returns the ``Sweep`` with its frequency-response table.

    Args:
        case: a ``Case``, a case file's path or a dict.
        beta: frequency ratios: a list, an array, or ``"A:B:N"`` as the program's ``--beta``
            (default: each point keeps the case's own frequency).
        sets: {key: value}: a list (or 1-D array) sweeps the key over its values, every
            combination with the other swept keys and ``beta``; a scalar holds for every point.
            ``{"screens.0.solidity": [0.3, 0.5, 0.7], "time.end": 30.0}``.
        out: the sweep directory (default ``out/<case name>_sweep``), as ``sloshsph sweep --out``.
        jobs: points at the same time; threads: OpenMP threads per point (default cores / jobs).
        retry_failed: run again the points that failed before.
        check: raise ``RunFailed`` when a point did not complete (the exception's ``result`` is
            the Sweep, table included).

    The same command again skips the points already finished, and refuses a directory made
    with other settings (``CaseError``). Ctrl-C stops every running point cleanly (they resume
    on the next call), writes the table of what finished, and raises ``Interrupted``.
    """
    case = as_case(case)
    fixed, axes = _axes_and_fixed(case, sets)
    directory = os.fspath(out) if out is not None else os.path.join("out", case.name + "_sweep")
    points = _core.plan_sweep(case._text, case.source, case.name, fixed, _betas(beta), axes, directory)
    if int(jobs) < 1:
        raise ValueError(f"jobs must be a positive number, not {jobs!r}")
    threads = int(threads) if threads else max(1, (os.cpu_count() or 1) // int(jobs))
    queue = [p for p in points if not _already_done(case, fixed, p, retry_failed)]
    os.makedirs(directory, exist_ok=True)
    done, running, interrupted = len(points) - len(queue), {}, False

    def say(what, point):
        if progress:
            sys.stderr.write(f"sweep: {what:<9} {point['label']}   [{done} done, {len(running)} running, "
                             f"{len(queue)} left]\n")

    try:
        while queue or running:
            while queue and len(running) < int(jobs):
                point = queue.pop(0)
                running[point["label"]] = (_start(case, fixed, point, threads), point)
                say("started", point)
            for label, (child, point) in list(running.items()):
                code = child.poll()
                if code is None:
                    continue
                del running[label]
                done += 1
                say({0: "completed", 4: "stopped"}.get(code, "FAILED"), point)
            _time.sleep(0.05)
    except KeyboardInterrupt:
        interrupted = True
        for child, _ in running.values():  # a notebook's interrupt reaches this process only
            child.send_signal(signal.SIGINT)
        for child, _ in running.values():
            child.wait()
    table = _core.frequency_response_csv(case._text, case.source, case.name, fixed, axes, points)
    with open(os.path.join(directory, "frequency_response.csv"), "w", encoding="utf-8") as f:
        f.write(table)
    result = Sweep(directory, points)
    if interrupted:
        raise Interrupted(f"sweep interrupted; the same call continues it ({directory})", result)
    if check and result.failed:
        raise RunFailed(f"{len(result.failed)} of {len(points)} points did not complete: "
                        f"{', '.join(result.failed)} (see their .log files in {directory})", result)
    return result
