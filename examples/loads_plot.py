"""A run's loads: the pantograph's hinge forces and latch torques through latch-up.

Reads the loads as arrays with their names and units, shades where the
rigid model cannot determine them, and plots with matplotlib.

    PYTHONPATH=build/python /usr/bin/python3 examples/loads_plot.py [OUT_DIR]
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

run = unfurl.simulate("pantograph", t_end=9, sample=0.002)
loads, t = run.loads, run.t
fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
for j in ("j1", "j2", "j3", "j4"):
    force = np.linalg.norm(np.column_stack([loads[f"hinge_force.{j}.{x}"] for x in "xyz"]), axis=1)
    top.plot(t, force, label=f"|hinge force| {j}")
    bottom.plot(t, loads[f"latch_torque.{j}"], label=f"latch {j}")
# Where the rigid loops are redundant the reactions are the minimum-norm ones.
indeterminate = loads["determinate"] == 0
top.fill_between(t, 0, 1, where=indeterminate, transform=top.get_xaxis_transform(), color="0.85",
                 label="indeterminate (minimum-norm)")
top.set_ylabel(f"force, {loads.unit('hinge_force.j1.x')}")
bottom.set_ylabel(f"torque, {loads.unit('latch_torque.j1')}")
bottom.set_xlabel("t, s")
top.set_xlim(7.2, 9)
for ax in (top, bottom):
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
peak = run.summary["peak_hinge_force"]["j1"]
top.set_title(f"pantograph: peak hinge force at j1 {peak['value']:.1f} N at t = {peak['t']:.4f} s")
path = os.path.join(out, "pantograph_loads.png")
fig.savefig(path, dpi=100, bbox_inches="tight")
print("plot", path)
