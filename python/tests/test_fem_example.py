"""The FE-model example end to end: boom_fem.py writes the .fem the magnetometer boom reads."""
import os
import shutil
import subprocess
import sys

import unfurl

FEM = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "fem")


def test_the_converter_writes_the_model_the_example_deploys(tmp_path):
    # Regenerated here (another BLAS may flip a mode's sign: the body is
    # the same), then deployed: the same latch-up as the committed file's.
    subprocess.run([sys.executable, os.path.join(FEM, "boom_fem.py"), str(tmp_path / "boom.fem")], check=True)
    shutil.copy(os.path.join(FEM, "magnetometer_boom.yaml"), tmp_path)
    fresh = unfurl.simulate(unfurl.load(str(tmp_path / "magnetometer_boom.yaml")), t_end=5.5)
    committed = unfurl.simulate(unfurl.load(os.path.join(FEM, "magnetometer_boom.yaml")), t_end=5.5)
    torque = committed.summary["peak_latch_torque"]["hinge"]["value"]
    assert torque > 1
    assert abs(fresh.summary["peak_latch_torque"]["hinge"]["value"] - torque) < 1e-6 * torque
    assert fresh.summary["latch_time"] == committed.summary["latch_time"]
