"""The z-fold wing with rigid panels against the same wing with flexible ones.

Runs the built-in zfold (with the same tip sensor as zfold_flexible's,
added by --set), zfold_flexible (panels as beams) and zfold_plates (panels
as plates), and writes what an engineer sizing the
hinges and latches compares: deployment time (the last latch), peak latch
torque, peak hinge force, the latch-up shock at the outer panel's tip (g)
and the deployed wing's first frequency (unfurl modes about the latched
end state). Prints the table as Markdown and plots the tip's acceleration
through the latch-ups.

The shock is given twice: the peak over every integrator step (what
summary.json reports), and the peak of the acceleration sampled every
0.1 ms and low-passed at 200 Hz (zero phase, a second-order Butterworth's
magnitude applied forward and back), which keeps the panels' own
modes (13-75 Hz latched; the plates' from 16.7 Hz) and leaves out the kHz ringing of the panels'
stiff stretch and in-plane constraint modes, which the latch's damper
sets off the instant it engages (its torque c_L q' steps on).

    PYTHONPATH=build/python /usr/bin/python3 examples/zfold_flexible_comparison.py [OUT_DIR]
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import unfurl  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "out/examples"
os.makedirs(out, exist_ok=True)

TIP = "[{name: tip, body: panel_A3, point: [0, 0.6, 0], frame: body, measure: [acceleration]}]"
scenes = {"rigid": unfurl.load("zfold", set={"sensors": TIP}), "flexible, as beams": unfurl.load("zfold_flexible"),
          "flexible, as plates": unfurl.load("zfold_plates")}
runs = {name: unfurl.simulate(scene, sample=1e-4) for name, scene in scenes.items()}
CUTOFF_HZ = 200
for name, run in runs.items():
    if run.status != "finished":
        sys.exit(f"{name}: {run.failure}")


def largest(peaks):
    """The largest of summary.json's per-joint peaks, and its joint."""
    joint = max(peaks, key=lambda j: peaks[j]["value"])
    return peaks[joint]["value"], joint


def first_frequency(scene):
    """The deployed wing's lowest vibration frequency (about its latched end state)."""
    m = unfurl.modes(scene)
    vibrating = [f for f, kind in zip(m.frequency_hz, m.kind) if kind == "elastic"]
    return min(vibrating)


def low_passed(x, dt):
    """x through a second-order Butterworth low-pass at CUTOFF_HZ, forward and back (zero phase).

    By FFT, so the record is taken as periodic: its two ends (the wing at
    rest, and settled) meet smoothly, far from the latch-ups.
    """
    f = np.fft.rfftfreq(len(x), dt)
    return np.fft.irfft(np.fft.rfft(x) / (1 + (f / CUTOFF_HZ) ** 4), len(x))


def peak_hinge_force_low_passed(run):
    """The largest hinge force over the joints, each component low-passed as the shock is."""
    dt = run.t[1] - run.t[0]
    largest = (0.0, "")
    for j in ("j1", "j2", "j3", "j4"):
        f = np.stack([low_passed(run.loads[f"hinge_force.{j}.{c}"], dt) for c in "xyz"])
        largest = max(largest, (float(np.max(np.linalg.norm(f, axis=0))), j))
    return largest


def tip_g(run, filtered=False):
    dt = run.t[1] - run.t[0]
    a = np.stack([run.sensors[f"tip.acceleration.{c}"] for c in "xyz"])
    if filtered:
        a = np.stack([low_passed(x, dt) for x in a])
    return np.linalg.norm(a, axis=0) / 9.80665


rows = []
for name, run in runs.items():
    s = run.summary
    latch_torque, latch_joint = largest(s["peak_latch_torque"])
    hinge_force, hinge_joint = largest(s["peak_hinge_force"])
    rows.append((name, max(s["latch_time"].values()), latch_torque, latch_joint, hinge_force, hinge_joint,
                 peak_hinge_force_low_passed(run), s["peak_acceleration"]["tip"]["g"], np.max(tip_g(run, filtered=True)),
                 first_frequency(scenes[name]), run.wall_time))

print(f"| panels | deployed (last latch) | peak latch torque | peak hinge force, every step |"
      f" peak hinge force, 0-{CUTOFF_HZ} Hz | tip shock, every step | tip shock, 0-{CUTOFF_HZ} Hz |"
      " deployed first frequency | run time |")
print("|---|---|---|---|---|---|---|---|---|")
for name, deployed, torque, tj, force, fj, (force_low, fj_low), g, g_low, f1, wall in rows:
    print(f"| {name} | {deployed:.4f} s | {torque:.2f} N m ({tj}) | {force:.1f} N ({fj}) | {force_low:.1f} N ({fj_low}) |"
          f" {g:.2f} g | {g_low:.2f} g | {f1:.3f} Hz | {wall:.2f} s |")

fig, axes = plt.subplots(2, 1, figsize=(9, 6.5))
for name, run in runs.items():
    axes[0].plot(run.t, tip_g(run, filtered=True), lw=0.8, label=f"panels {name}")
axes[0].set_xlim(0, 20)
axes[0].set_ylabel(f"tip acceleration 0-{CUTOFF_HZ} Hz, g")
axes[0].set_title("z-fold wing: the outer panel tip's acceleration, rigid and flexible panels (beams, plates)",
                  fontsize=10)
axes[0].legend(fontsize=8)
axes[0].grid(True, alpha=0.3)
# The outer panel's latch-up (j4), close up: unfiltered (0.1 ms samples) and filtered.
t_latch = runs["flexible, as beams"].summary["latch_time"]["j4"]
for name, run in runs.items():
    line, = axes[1].plot(run.t, tip_g(run), lw=0.5, alpha=0.6, label=f"{name}, every 0.1 ms")
    axes[1].plot(run.t, tip_g(run, filtered=True), lw=1.4, color=line.get_color(), label=f"{name}, 0-{CUTOFF_HZ} Hz")
axes[1].set_xlim(t_latch - 0.02, t_latch + 0.12)
axes[1].set_xlabel("t, s")
axes[1].set_ylabel("tip acceleration, g")
axes[1].set_title(f"the outer panel's latch-up (j4, t = {t_latch:.3f} s)", fontsize=9)
axes[1].legend(fontsize=7, ncol=2)
axes[1].grid(True, alpha=0.3)
fig.tight_layout()
path = os.path.join(out, "zfold_flexible_shock.png")
fig.savefig(path, dpi=100)
print("plot", path)
