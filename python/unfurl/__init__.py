"""unfurl: the deployment of spacecraft solar arrays and other jointed mechanisms.

Scenes are loaded from a file or a built-in name and changed by the same
paths as the command line's --set; runs return numpy arrays with the column
names, units and frames of the CLI's files; modes, studies and pictures are
here too. Every function has a docstring: help(unfurl.simulate).

    import unfurl
    scene = unfurl.load("pantograph", set={"springs.j1.stiffness": 0.102})
    run = unfurl.simulate(scene, t_end=9)
    run.loads["hinge_force.j1.y"], run.summary["peak_hinge_force"]["j1"]["value"]
"""

import json
import math
import os
import warnings

import numpy as np

from . import _unfurl
from ._unfurl import SceneError

SceneError.__doc__ = ("A scene or study that cannot be read or is not valid: the message names the file, line "
                      "and column (for a file) and the field's path. A ValueError.")

__all__ = [
    "SceneError", "Scene", "SceneBuilder", "Table", "Run", "Modes", "Cases",
    "load", "builtin_scenes", "generate", "simulate", "modes", "study", "render_frame", "plots",
]


def _yaml(value):
    """A Python value as YAML text for a --set override."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float, np.integer, np.floating)):
        x = float(value)
        if not math.isfinite(x):
            raise ValueError(f"{value!r}: a scene value must be finite")
        return repr(int(value)) if isinstance(value, (int, np.integer)) else repr(x)
    if isinstance(value, str):
        return value
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k}: {_yaml(v)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_yaml(v) for v in value) + "]"
    raise TypeError(f"{type(value).__name__} is not a scene value (numbers, strings, lists and dicts are)")


def _pairs(overrides):
    if overrides is None:
        return []
    if not isinstance(overrides, dict):
        raise TypeError("set: expected a dict of path: value, as --set path=value")
    return [(str(path), _yaml(value)) for path, value in overrides.items()]


class Scene:
    """A scene: the mechanism, its initial state and how to run it.

    Made by unfurl.load() or SceneBuilder.build(). Immutable: set() returns
    a new scene. Its lists (bodies, joints, positions, velocities, latches,
    loops, sensors) name what the run's columns and the --set paths name.
    """

    def __init__(self, native):
        self._native = native
        # What is valid but likely a mistake (an angle in degrees), as the CLI warns.
        for warning in native._warnings():
            warnings.warn(f"{native.source}: {warning}", UserWarning, stacklevel=3)

    name = property(lambda self: self._native.name, doc="The scene's name.")
    description = property(lambda self: self._native.description, doc="Its description.")
    source = property(lambda self: self._native.source, doc="The file it came from, or 'built-in:NAME'.")
    bodies = property(lambda self: self._native.bodies, doc="Body names, in order.")
    joints = property(lambda self: self._native.joints, doc="Joint names (joint i carries body i).")
    positions = property(lambda self: self._native.positions, doc="Names of the position coordinates q.")
    velocities = property(lambda self: self._native.velocities, doc="Names of the velocity coordinates.")
    latches = property(lambda self: self._native.latches, doc="The joints that carry latches.")
    loops = property(lambda self: self._native.loops, doc="The closed loops' names.")
    sensors = property(lambda self: self._native.sensors, doc="The sensors' names.")
    t_end = property(lambda self: self._native.t_end, doc="The run's end time in the scene, s.")

    def set(self, path=None, value=None, **kwargs):
        """A copy with values changed by their --set paths.

        scene.set("springs.j1.stiffness", 0.2), or several at once with a
        dict: scene.set({"springs.j1.stiffness": 0.2, "run.t_end": 9}).
        Raises SceneError naming the path and what is wrong.
        """
        if kwargs:
            raise TypeError("set() takes a path and a value, or a dict of them")
        changes = path if isinstance(path, dict) else {path: value}
        return Scene(self._native._overridden(_pairs(changes)))

    def to_yaml(self):
        """The scene as a scene file's text (it reads back to the same run)."""
        return self._native._yaml()

    def save(self, path):
        """Writes the scene file to path."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.to_yaml())

    def __repr__(self):
        return f"<unfurl.Scene {self.name!r}: {len(self.bodies)} bodies, {len(self.loops)} loops>"


def builtin_scenes():
    """The names of the built-in scenes."""
    return list(_unfurl._builtin_scenes())


def load(name="pantograph", set=None):
    """Loads a scene: a file path (.yaml) or a built-in name (builtin_scenes()).

    set: a dict of --set paths and values applied as the file is read
    ({"springs.j1.stiffness": 0.102, "bodies.panel_A1.mass": 2.1}).
    Raises SceneError with file:line:column and the field path on a bad file.
    """
    if not isinstance(name, (str, os.PathLike)):
        raise TypeError(f"load: expected a path or a built-in name, got {type(name).__name__}")
    return Scene(_unfurl._load(os.fspath(name), _pairs(set)))


def generate(kind, n, compliant=False, flexible=False, snubbers=True):
    """A scene of any size, as `unfurl generate` writes it.

    kind: "pantograph" (n stages: 3n + 2 bodies, n loops; compliant=True
    for cross-links on bushings, a tree; flexible=True for plate panels
    whose loops close through their bending; either one's hinges stand on
    snubbers unless snubbers=False), "zfold" (n panels), "chain" (n links),
    "rods" (n parallel rods) or "beam" (n segments). n = 3 gives the
    built-in pantograph and zfold, and with snubbers=False
    pantograph_compliant and pantograph_flexible. Raises ValueError on a
    bad kind, size or combination.
    """
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)):
        raise TypeError(f"generate: the size is a whole number, got {n!r}")
    if not 1 <= n <= 1_000_000:
        raise ValueError(f"generate: the size runs from 1 to 1000000, got {n}")
    return Scene(_unfurl._generate(str(kind), int(n), bool(compliant), bool(flexible), bool(snubbers)))


class SceneBuilder:
    """Builds a scene in code, naming bodies and joints as a scene file does.

        b = unfurl.SceneBuilder("pendulum")
        b.fixed_base("ground")
        b.gravity([0, 0, -9.81])
        b.body("rod", parent="ground", mass=1.5, inertia=[0.02, 0.02, 0.005], com=[0, 0, -0.4],
               joint=dict(name="h", type="revolute", axis=[1, 0, 0]))
        b.spring("h", stiffness=3.0, free_position=0)
        b.initial("h", q=[0.3])
        scene = b.build()

    Methods: fixed_base, free_base, body (joint: a dict with name, type,
    axis, axis2, parent_point, child_point and an optional compliance dict),
    spring, damper, friction, latch, driver (joint, profile "move" or
    "spin_up", amount, duration, start), point_spring, bushing, applied_force,
    gravity, loop, sensor, initial, run, build. Each checks what it is
    given; build() checks the whole scene as a file is checked and raises
    SceneError naming the field.
    """

    def __init__(self, name, description=""):
        self._native = _unfurl._SceneBuilder(name, description)

    def __getattr__(self, method):
        call = getattr(self._native, method)

        def forward(*args, **kwargs):
            call(*args, **kwargs)
            return self
        forward.__doc__ = call.__doc__
        return forward

    def build(self):
        """The scene, validated (SceneError names what is wrong)."""
        return Scene(self._native.build())


class Table:
    """Columns of numbers over the samples, as the CLI's CSV files hold them.

    table["q.j1"] is a column (a numpy array); table.names, table.units and
    table.frames describe the columns; table.data is samples x columns;
    table.unit("q.j1") is "rad".
    """

    def __init__(self, names, units, frames, data):
        self.names, self.units, self.frames = list(names), list(units), list(frames)
        self.data = np.asarray(data)
        self._index = {n: k for k, n in enumerate(self.names)}

    def __getitem__(self, name):
        try:
            return self.data[:, self._index[name]]
        except KeyError:
            raise KeyError(f"no column {name!r} (table.names lists them)") from None

    def __contains__(self, name):
        return name in self._index

    def __len__(self):
        return self.data.shape[0]

    def unit(self, name):
        """The column's unit ("" for a pure number)."""
        return self.units[self._index[name]]

    def frame(self, name):
        """The frame the column is given in ("" where none applies)."""
        return self.frames[self._index[name]]

    def as_dict(self):
        """{name: column}."""
        return {n: self[n] for n in self.names}

    def __repr__(self):
        return f"<unfurl.Table: {len(self)} rows x {len(self.names)} columns>"


class Run:
    """A finished (or failed) run.

    trajectory, loads, sensors: Tables with the columns of trajectory.csv,
    loads.csv and sensors.csv; events: [(t, joint)] of the latches;
    summary: summary.json as a dict (the same peaks the CLI prints);
    status: "finished", "failed" or "cancelled"; failure: what failed.
    """

    def __init__(self, native, scene):
        self._native, self.scene = native, scene
        self.trajectory = Table(*native._trajectory())
        self.loads = Table(*native._loads())
        self.sensors = Table(*native._sensors())
        self.events = list(native._events())
        self.summary = json.loads(native._summary_json())

    status = property(lambda self: self._native.status, doc="finished, failed or cancelled")
    failure = property(lambda self: self._native.failure, doc="What failed, where and why ('' if nothing).")
    wall_time = property(lambda self: self._native.wall_time, doc="Seconds the run took.")

    @property
    def t(self):
        """The sample times, s."""
        return self.trajectory["t"]

    def __repr__(self):
        return f"<unfurl.Run of {self.scene.name!r}: {self.status}, {len(self.trajectory)} samples>"


def simulate(scene, t_end=None, rtol=None, atol=None, integrator=None, sample=None, set=None, progress=None):
    """Simulates a scene (a Scene, a file path or a built-in name) and returns a Run.

    t_end, rtol, atol, integrator ("cvode-bdf", "cvode-adams", "arkode-erk",
    "arkode-dirk", "rk4") and sample override the scene's run settings, as
    --t-end, --rtol, ... do; set: more --set overrides. progress: called
    with the simulated time about every 50 ms. The GIL is released while it
    runs; Ctrl+C stops it (or its summary) and raises KeyboardInterrupt. A failed run is
    returned with status "failed" and what was computed up to there.
    """
    if not isinstance(scene, Scene):
        scene = load(scene)
    changes = dict(set or {})
    for key, value in (("t_end", t_end), ("rtol", rtol), ("atol", atol), ("integrator", integrator),
                       ("sample", sample)):
        if value is not None:
            changes["run." + key] = value
    if changes:
        scene = scene.set(changes)
    if progress is not None and not callable(progress):
        raise TypeError("progress: expected a function of the simulated time")
    return Run(_unfurl._simulate(scene._native, progress), scene)


class Modes:
    """Natural frequencies, damping ratios and mode shapes (unfurl modes).

    frequency_hz, damping_ratio, damped_frequency_hz: arrays over the modes;
    kind: "elastic", "rigid body", "mechanism" or "unstable" per mode;
    shapes: modes x coordinates (each row's largest entry +1); coordinates:
    the velocity coordinates' names; q: the positions linearized about;
    state: how they were chosen.
    """

    def __init__(self, d):
        self.frequency_hz = np.asarray(d["frequency_hz"])
        self.damping_ratio = np.asarray(d["damping_ratio"])
        self.damped_frequency_hz = np.asarray(d["damped_frequency_hz"])
        self.kind = list(d["kind"])
        self.shapes = np.asarray(d["shapes"])
        self.coordinates = list(d["coordinates"])
        self.q = np.asarray(d["q"])
        self.state = d["state"]
        self.loop_rank = d["loop_rank"]
        self.weak_loop_directions = d["weak_loop_directions"]
        self.equilibrium_offset = d["equilibrium_offset"]

    def __len__(self):
        return len(self.kind)

    def __repr__(self):
        shown = ", ".join(f"{f:.4g}" for f in self.frequency_hz[:4])
        return f"<unfurl.Modes: {len(self)} modes, {shown} Hz ...>"


def modes(scene, at=None, q=None, settle=None):
    """The scene's modes about where its run ends, settled to its static equilibrium.

    at: a run's state at this time instead (not settled unless settle=True);
    q: given positions (len(scene.positions)) instead. Loops are respected
    (independent coordinates); a free-floating bus has six rigid-body modes.
    Returns Modes.
    """
    if not isinstance(scene, Scene):
        scene = load(scene)
    if q is not None:
        q = [float(x) for x in q]
    return Modes(_unfurl._modes(scene._native, at, q, settle))


class Cases:
    """A study's cases: case ids, status ("deployed", "not deployed",
    "failed"), reasons, the varied inputs and every output, as cases.csv.

    inputs and outputs are Tables over the cases (columns named as in
    cases.csv, without their units; outputs.unit(name) gives them).
    """

    def __init__(self, d):
        self.case, self.failure, self.status, self.reason = d["case"], d["failure"], d["status"], d["reason"]
        n = len(self.case)
        self.inputs = Table(d["inputs"], [""] * len(d["inputs"]), [""] * len(d["inputs"]),
                            np.asarray(d["input_data"]).reshape(n, len(d["inputs"])))
        self.outputs = Table(d["outputs"], d["output_units"], [""] * len(d["outputs"]),
                             np.asarray(d["output_data"]).reshape(n, len(d["outputs"])))

    def __len__(self):
        return len(self.case)

    def deployed(self):
        """A boolean mask of the deployed cases."""
        return np.array([s == "deployed" for s in self.status])

    def __repr__(self):
        return f"<unfurl.Cases: {len(self)} cases, {int(self.deployed().sum())} deployed>"


def study(study, jobs=None, out=None):
    """Runs a study on the machine's cores and returns its Cases.

    study: a study file's path, or a dict with a study file's keys
    ({"scene": "pantograph", "vary": [{"path": "springs.j1.stiffness",
    "values": [0.09, 0.1, 0.11]}]}). jobs: threads (default: every core).
    out: a directory for the CLI's files (cases.csv, summary.json,
    STUDY.md, plots); without it nothing is written. Ctrl+C stops it.
    """
    if isinstance(study, dict):
        text = "\n".join(f"{k}: {_yaml(v)}" for k, v in study.items()) + "\n"
        return Cases(_unfurl._study(text, True, os.getcwd(), out, jobs))
    if not isinstance(study, (str, os.PathLike)):
        raise TypeError("study: expected a path or a dict")
    return Cases(_unfurl._study(os.fspath(study), False, "", out, jobs))


def render_frame(run, t, width=640, height=360, camera="iso", loads=False, load_scale=1.0):
    """The run at time t drawn headless (EGL, else OSMesa): an array height x width x 3 (uint8).

    camera: a preset (iso, side, top, end, bottom) or "AZ,EL,DIST".
    loads: draw the hinge forces and latch torques as arrows, as
    `unfurl render --loads` does (load_scale: their length, times the default).
    """
    if not isinstance(run, Run):
        raise TypeError("render_frame: expected a Run (from unfurl.simulate)")
    if not float(load_scale) > 0:
        raise ValueError("render_frame: load_scale must be > 0")
    return _unfurl._frame(run._native, float(t), int(width), int(height), camera,
                          float(load_scale) if loads else 0.0)


def plots(run, directory, width=1280, height=720):
    """Writes the run's standard plots (angles, rates, loads, energy, ...) as PNGs; their paths."""
    if not isinstance(run, Run):
        raise TypeError("plots: expected a Run (from unfurl.simulate)")
    return list(_unfurl._plots(run._native, os.fspath(directory), int(width), int(height)))
