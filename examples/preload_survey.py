"""An off-nominal survey: the z-fold's deployment time against its springs' preload.

Every spring's preload scaled together from 80 % to 120 % (a study, run on
every core), plotted with matplotlib.

    PYTHONPATH=build/python /usr/bin/python3 examples/preload_survey.py [OUT_DIR]
"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import unfurl  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else "out/examples"
os.makedirs(out, exist_ok=True)

factors = [0.8, 0.85, 0.9, 0.95, 1.0, 1.05, 1.1, 1.15, 1.2]
cases = unfurl.study({
    "scene": "zfold",
    "set": {"run.t_end": 30, "run.rtol": 1e-8},
    "combine": "zip",
    "vary": [{"path": "springs.*.preload", "values": factors}],
})
deployed = cases.deployed()
preload = cases.inputs["springs.j1.preload_factor"]
time = cases.outputs["deployment_time"]
for p, t, ok in zip(preload, time, deployed):
    print(f"preload x {p:.2f}: " + (f"deployed at {t:.3f} s" if ok else "not deployed"))

fig, ax = plt.subplots(figsize=(7, 4))
order = [k for k in preload.argsort() if deployed[k] and cases.case[k] != "nominal"]
ax.plot(preload[order], time[order], "o-", label="cases")
nominal = cases.case.index("nominal")
ax.plot(preload[nominal], time[nominal], "s", color="C1", label="nominal")
ax.legend()
ax.set_xlabel("every spring's preload, x nominal")
ax.set_ylabel("deployment time (last latch), s")
ax.set_title("z-fold: deployment time against preload")
ax.grid(True, alpha=0.3)
path = os.path.join(out, "deployment_time_against_preload.png")
fig.savefig(path, dpi=100, bbox_inches="tight")
print("plot", path)
