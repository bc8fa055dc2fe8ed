"""Runs: arrays equal to the CLI's files, summaries with the CLI's peaks, progress, Ctrl+C."""
import csv
import json
import os
import signal
import threading
import time

import numpy as np
import pytest

import unfurl


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    names = [cell.split(" [")[0] for cell in rows[0]]
    return names, np.array([[float(x) if x else np.nan for x in row] for row in rows[1:]])


@pytest.mark.parametrize("scene,args", [
    ("zfold", ["--t-end", "9"]),
    ("pantograph", ["--t-end", "8", "--set", "springs.j1.stiffness=0.102"]),
    ("pantograph_compliant", ["--t-end", "8"]),
])
def test_a_runs_arrays_are_the_clis_files(tmp_path, cli, scene, args):
    cli("simulate", scene, *args, "--out", str(tmp_path), "--quiet")
    overrides = dict(a.split("=", 1) for a in args[3::2]) if "--set" in args else {}
    run = unfurl.simulate(unfurl.load(scene, set=overrides), t_end=float(args[1]))
    for name, table in (("trajectory", run.trajectory), ("loads", run.loads)):
        names, data = read_csv(tmp_path / f"{name}.csv")
        assert names == table.names
        assert np.array_equal(data, table.data, equal_nan=True), name
    with open(tmp_path / "summary.json") as f:
        summary = json.load(f)
    for key in ("peak_latch_torque", "peak_hinge_force", "peak_hinge_moment", "latch_time", "steps",
                "loads_determinate", "energy_final"):
        assert run.summary.get(key) == summary.get(key), key
    assert run.events == [(float(t), j) for t, j in sorted((v, k) for k, v in summary["latch_time"].items())]


def test_units_and_frames_come_with_the_columns():
    run = unfurl.simulate("zfold", t_end=1)
    assert run.trajectory.unit("q.j1") == "rad"
    assert run.loads.unit("hinge_force.j1.y") == "N"
    assert run.loads.frame("hinge_force.j1.y") == "child body frame"
    assert run.summary["units"]["peak_hinge_force"] == "N"


def test_sensors_come_as_a_table():
    scene = unfurl.load("zfold", set={"sensors": [{"name": "tip", "body": "panel_A3", "point": [0, 0.6, 0]}]})
    run = unfurl.simulate(scene, t_end=6)
    a = np.linalg.norm(np.column_stack([run.sensors[f"tip.acceleration.{x}"] for x in "xyz"]), axis=1)
    assert run.sensors.unit("tip.acceleration.x") == "m/s^2"
    assert run.summary["peak_acceleration"]["tip"]["value"] >= a.max()
    assert run.summary["peak_acceleration"]["tip"]["g"] > 2


def test_progress_is_reported():
    times = []
    unfurl.simulate("zfold", t_end=20, rtol=1e-10, progress=times.append)
    assert times and times[-1] == pytest.approx(20)
    assert all(b >= a for a, b in zip(times, times[1:]))


def threads():
    return len(os.listdir("/proc/self/task"))


def test_ctrl_c_cancels_the_run_and_leaves_no_thread():
    before = threads()
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        # about 3 s: the round-off guard held off (with it the run takes 0.3 s)
        unfurl.simulate("pantograph", t_end=20, rtol=1e-12, set={"run.roundoff_guard": "false"})
    timer.join()
    assert threads() == before


def test_ctrl_c_stops_the_summary_too(tmp_path, cli):
    # A 200-stage compliant array's first millisecond: its integration is
    # short, its summary (the torque margins of 402 driven joints at 101
    # angles each, the clearance of 402 panels) takes most of the call.
    path = tmp_path / "array.yaml"
    cli("generate", "pantograph", "--stages", "200", "--compliant", "-o", str(path))
    settings = dict(t_end=0.001, sample=0.001, rtol=1e-7, atol=1e-9)
    start = time.monotonic()
    unfurl.simulate(str(path), **settings)
    whole = time.monotonic() - start
    # Ctrl+C 50 ms after the integration has reached its end.
    timers = []

    def interrupt_once_integrated(t):
        if t >= settings["t_end"] and not timers:
            timers.append(threading.Timer(0.05, lambda: os.kill(os.getpid(), signal.SIGINT)))
            timers[0].start()

    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        unfurl.simulate(str(path), progress=interrupt_once_integrated, **settings)
    interrupted = time.monotonic() - start
    timers[0].join()
    assert interrupted < 0.5 * whole, (interrupted, whole)


def test_a_failed_run_keeps_what_was_computed():
    run = unfurl.simulate("pantograph", integrator="rk4", set={"run.dt": 0.05}, t_end=2)
    assert run.status == "failed"
    assert "t =" in run.failure
    assert len(run.trajectory) > 0


def test_bad_arguments_raise_not_crash():
    with pytest.raises(unfurl.SceneError, match="run.t_end"):
        unfurl.simulate("zfold", t_end=-1)
    with pytest.raises(unfurl.SceneError, match="integrator"):
        unfurl.simulate("zfold", integrator="euler")
    with pytest.raises(TypeError):
        unfurl.simulate("zfold", progress=3)
    with pytest.raises(TypeError):
        unfurl.render_frame("not a run", 0)
