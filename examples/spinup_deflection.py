"""Simo and Vu-Quoc's spin-up: the flexible beam's tip deflection with and without geometric stiffening.

Runs the built-in spinup_beam twice, the second time as a plain linear
floating-frame model (geometric_stiffening: false), and plots the largest
deflection of the beam's mesh from its frame (the tip's) against time.
Without the stiffening the spin softens the first mode past zero once the
hub turns faster than 3.8 rad/s, and the tip runs away.

    PYTHONPATH=build/python /usr/bin/python3 examples/spinup_deflection.py [OUT_DIR]
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

stiffened = unfurl.simulate("spinup_beam")
plain = unfurl.simulate("spinup_beam", set={"bodies.beam.flexible.geometric_stiffening": "false"})
fig, ax = plt.subplots(figsize=(8, 4.5))
ax.plot(stiffened.t, stiffened.loads["deflection.beam"], label="with geometric stiffening (foreshortening)")
ax.plot(plain.t, plain.loads["deflection.beam"], "--", label="plain linear floating frame")
ax.axvline(15, color="0.6", lw=0.8)
ax.text(15.2, 0.9, "6 rad/s reached", color="0.4", fontsize=8)
ax.set_ylim(0, 1.2)
ax.set_xlim(0, 30)
ax.set_xlabel("t, s")
ax.set_ylabel(f"tip deflection, {stiffened.loads.unit('deflection.beam')}")
peak = np.max(stiffened.loads["deflection.beam"])
ax.set_title(f"spin-up of a 10 m beam to 6 rad/s: largest tip deflection {peak:.4f} m "
             f"(without stiffening: {np.max(plain.loads['deflection.beam']):.1e} m)", fontsize=10)
ax.grid(True, alpha=0.3)
ax.legend(fontsize=8)
path = os.path.join(out, "spinup_deflection.png")
fig.savefig(path, dpi=100, bbox_inches="tight")
print("plot", path)
