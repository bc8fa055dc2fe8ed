"""Modes as the CLI gives them, studies on the machine's cores, headless pictures."""
import json

import numpy as np
import pytest

import unfurl


def test_modes_are_the_clis(tmp_path, cli):
    cli("modes", "zfold", "--out", str(tmp_path), "--quiet")
    with open(tmp_path / "modes.json") as f:
        expected = json.load(f)
    m = unfurl.modes("zfold")
    assert len(m) == len(expected["modes"])
    for k, mode in enumerate(expected["modes"]):
        assert m.frequency_hz[k] == mode["frequency_hz"]
        assert m.damping_ratio[k] == mode["damping_ratio"]
        assert list(m.shapes[k]) == [mode["shape"][c] for c in m.coordinates]
    assert m.kind == ["elastic"] * 4
    assert "settled" in m.state


def test_modes_of_a_free_bus_and_at_given_positions():
    free = unfurl.modes("zfold_free")
    assert free.kind[:6] == ["rigid body"] * 6
    scene = unfurl.load("pendulum")
    given = unfurl.modes(scene, q=[0.0])
    assert len(given) == 1 and given.frequency_hz[0] > 0


def test_a_study_made_in_python_runs_its_cases(tmp_path):
    cases = unfurl.study({"scene": "zfold", "set": {"run.t_end": 17},
                          "vary": [{"path": "springs.j1.stiffness", "values": [0.09, 0.1, 0.11]}]},
                         jobs=2, out=str(tmp_path))
    assert len(cases) == 4 and cases.case[0] == "nominal"
    assert list(cases.inputs["springs.j1.stiffness"]) == [0.1, 0.09, 0.1, 0.11]
    assert cases.deployed().sum() == 4
    assert cases.outputs.unit("deployment_time") == "s"
    assert (tmp_path / "cases.csv").exists() and (tmp_path / "STUDY.md").exists()
    # The same deployment time for the same values.
    assert cases.outputs["deployment_time"][0] == cases.outputs["deployment_time"][2]


def test_a_bad_study_raises_scene_error():
    with pytest.raises(unfurl.SceneError, match="vary"):
        unfurl.study({"scene": "zfold", "vary": [{"path": "springs.j9.stiffness", "values": [1]}]})


def test_a_frame_is_drawn_headless_and_plots_are_written(tmp_path):
    run = unfurl.simulate("pantograph", t_end=20, rtol=1e-8)
    image = unfurl.render_frame(run, 20, width=320, height=180)
    assert image.shape == (180, 320, 3) and image.dtype == np.uint8
    blue = (image[:, :, 2] > 70) & (image[:, :, 2] > image[:, :, 0].astype(int) + 40)
    assert blue.sum() > 500  # the deployed panels' cells
    # The loads as arrows, as render --loads draws them: the frame changes.
    loaded = unfurl.render_frame(run, 20, width=320, height=180, loads=True)
    assert (np.abs(loaded.astype(int) - image.astype(int)).sum(axis=2) > 60).sum() > 200
    with pytest.raises(ValueError):
        unfurl.render_frame(run, 20, loads=True, load_scale=0)
    paths = unfurl.plots(run, tmp_path, width=640, height=360)
    assert any(p.endswith("loads.png") for p in paths)
    assert all((tmp_path / p.split("/")[-1]).stat().st_size > 1000 for p in paths)


def test_every_public_function_has_a_docstring():
    for name in unfurl.__all__:
        assert getattr(unfurl, name).__doc__, name
