"""The FE-model examples end to end: boom_fem.py and panel_fem.py write the .fem files the example scenes read."""
import os
import shutil
import subprocess
import sys

import pytest

import unfurl

FEM = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "fem")


@pytest.mark.parametrize("converter, fem, scene, t_end", [("boom_fem.py", "boom.fem", "magnetometer_boom.yaml", 5.5),
                                                          ("panel_fem.py", "panel.fem", "deploying_panel.yaml", 2.0)])
def test_the_converter_writes_the_model_the_example_deploys(tmp_path, converter, fem, scene, t_end):
    # Regenerated here (another BLAS may flip a mode's sign: the body is
    # the same), then deployed: the same latch-up as the committed file's.
    subprocess.run([sys.executable, os.path.join(FEM, converter), str(tmp_path / fem)], check=True)
    shutil.copy(os.path.join(FEM, scene), tmp_path)
    fresh = unfurl.simulate(unfurl.load(str(tmp_path / scene)), t_end=t_end)
    committed = unfurl.simulate(unfurl.load(os.path.join(FEM, scene)), t_end=t_end)
    torque = committed.summary["peak_latch_torque"]["hinge"]["value"]
    assert torque > 1
    assert abs(fresh.summary["peak_latch_torque"]["hinge"]["value"] - torque) < 1e-6 * torque
    assert fresh.summary["latch_time"] == committed.summary["latch_time"]


def _plate_twin(tmp_path):
    # The same panel as unfurl's own plate (Bogner-Fox-Schmit elements,
    # consistent masses) instead of the file's ACM elements, lumped.
    text = open(os.path.join(FEM, "deploying_panel.yaml")).read()
    fem = "      fem: panel.fem\n"
    assert fem in text
    plate = ("      plate: {size: [0.9, 1.2], corner: [-0.45, 0, 0], bending_stiffness: 7435, poisson: 0.33,\n"
             "              mass_per_area: 3.7037037037037037, elements: [6, 8], root_edge: y0}\n"
             "      modes: 15\n")
    path = tmp_path / "plate_twin.yaml"
    path.write_text(text.replace(fem, plate))
    return unfurl.load(str(path))


def test_the_fe_panel_deploys_as_unfurls_own_plate(tmp_path):
    fe_scene = unfurl.load(os.path.join(FEM, "deploying_panel.yaml"))
    fe, plate = unfurl.simulate(fe_scene, t_end=2), unfurl.simulate(_plate_twin(tmp_path), t_end=2)
    # The lumped masses' second moment about the hinge is the trapezoidal
    # rule's, 0.8 % over the plate's: the swing takes 0.34 % longer.
    assert abs(fe.summary["latch_time"]["hinge"] / plate.summary["latch_time"]["hinge"] - 1) < 5e-3
    torque = plate.summary["peak_latch_torque"]["hinge"]["value"]
    assert abs(fe.summary["peak_latch_torque"]["hinge"]["value"] / torque - 1) < 1e-2
    # Deployed and latched: the first three modes (the latch's swing, the
    # panel's first bending and torsion), ACM and lumped against BFS and
    # consistent.
    fe_hz, plate_hz = unfurl.modes(fe_scene).frequency_hz[:3], unfurl.modes(_plate_twin(tmp_path)).frequency_hz[:3]
    for f, g in zip(fe_hz, plate_hz):
        assert abs(f / g - 1) < 3e-2

