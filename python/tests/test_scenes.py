"""Scenes from files, built-in names and code; --set paths; errors that name the field."""
import math

import pytest

import unfurl


def test_builtin_scenes_load_and_describe_themselves():
    assert "pantograph" in unfurl.builtin_scenes()
    scene = unfurl.load("pantograph")
    assert scene.name == "pantograph"
    assert scene.positions[:2] == ["j1", "j2"]
    assert scene.latches == ["j1", "j2", "j3", "j4", "j5", "j6", "j7", "j8"]
    assert scene.loops == ["A1", "A2", "A3"]


def test_set_changes_a_value_by_its_path_and_leaves_the_original():
    scene = unfurl.load("zfold")
    changed = scene.set("springs.j1.stiffness", 0.2)
    assert "stiffness: 0.2," in changed.to_yaml()
    assert "stiffness: 0.1," in scene.to_yaml()
    several = scene.set({"springs.j1.stiffness": 0.2, "run.t_end": 5})
    assert several.t_end == 5


def test_a_file_round_trips_through_yaml(tmp_path):
    scene = unfurl.load("pantograph_compliant")
    path = tmp_path / "copy.yaml"
    scene.save(path)
    back = unfurl.load(str(path))
    assert back.to_yaml() == scene.to_yaml()


def test_a_bad_file_raises_scene_error_with_line_column_and_field(tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text("name: bad\nbodies:\n  - {name: a, parent: base, mass: -1, inertia: [1, 1, 1],\n"
                    "     joint: {type: revolute, axis: [1, 0, 0], parent_point: [0, 0, 0], child_point: [0, 0, 0]}}\n")
    with pytest.raises(unfurl.SceneError) as error:
        unfurl.load(str(path))
    message = str(error.value)
    assert "bad.yaml:3:" in message and "bodies[0] (a).mass" in message and "negative mass" in message
    assert isinstance(error.value, ValueError)


def test_a_bad_path_or_value_raises_scene_error_naming_it():
    scene = unfurl.load("zfold")
    with pytest.raises(unfurl.SceneError, match="springs.j9"):
        scene.set("springs.j9.stiffness", 1.0)
    with pytest.raises(unfurl.SceneError, match="stiffness"):
        scene.set("springs.j1.stiffness", "soft")
    with pytest.raises(unfurl.SceneError, match="nothing: no such scene file, and no built-in scene"):
        unfurl.load("nothing")


def test_wrong_types_get_clear_messages():
    with pytest.raises(TypeError, match="a path or a built-in name"):
        unfurl.load(42)
    with pytest.raises(TypeError, match="dict of path"):
        unfurl.load("zfold", set=[("springs.j1.stiffness", 1)])
    with pytest.raises(TypeError, match="is not a scene value"):
        unfurl.load("zfold").set("springs.j1.stiffness", object())
    with pytest.raises(ValueError, match="finite"):
        unfurl.load("zfold").set("springs.j1.stiffness", math.nan)


def pendulum_builder():
    b = unfurl.SceneBuilder("pendulum", "a rod on a hinge")
    b.fixed_base("ground")
    b.gravity([0, 0, -9.81])
    b.body("rod", parent="ground", mass=1.5, inertia=[0.02, 0.02, 0.005], com=[0, 0, -0.4],
           joint=dict(name="h", type="revolute", axis=[1, 0, 0]))
    return b


def test_a_scene_built_in_code_runs_as_its_closed_form():
    b = pendulum_builder()
    b.initial("h", q=[0.01])
    b.run(t_end=2, rtol=1e-10, atol=1e-12)
    scene = b.build()
    run = unfurl.simulate(scene)
    # Small swings: theta(t) = 0.01 cos(omega t), omega^2 = m g d / I.
    omega = math.sqrt(1.5 * 9.81 * 0.4 / (0.02 + 1.5 * 0.16))
    expected = 0.01 * __import__("numpy").cos(omega * run.t)
    assert abs(run.trajectory["q.h"] - expected).max() < 2e-6
    # ... and writes a scene file that reads back to the same scene.
    assert unfurl.load  # noqa: the round trip below
    text = scene.to_yaml()
    assert "name: rod" in text and "gravity: [0, 0, -9.81]" in text


def test_a_driver_moves_the_rod_and_reports_its_torque():
    b = pendulum_builder()
    b.driver("h", profile="move", amount=math.pi / 2, duration=2)
    b.run(t_end=3, rtol=1e-10, atol=1e-12)
    run = unfurl.simulate(b.build())
    # tau = I_o theta'' + m g d sin(theta) at the state reached; held at
    # 90 degrees after the move, the weight's moment.
    theta = run.trajectory["q.h"]
    assert abs(theta[-1] - math.pi / 2) < 1e-8
    assert abs(run.loads["drive_torque.h"][-1] - 1.5 * 9.81 * 0.4) < 1e-8
    assert run.loads.unit("drive_torque.h") == "N m"


def test_a_limit_stops_the_rod_where_the_closed_form_says():
    # Released from 0.3 rad, the rod swings through the bottom to -0.3 rad;
    # a stiff limit at -0.1 rad turns it back there, so it never goes below
    # -0.1 rad by more than the limit's own deflection, and it leaves the
    # limit as fast as it came (no damping): it rises again to 0.3 rad.
    b = pendulum_builder()
    b.limit("h", stiffness=1e4, lower=-0.1)
    b.initial("h", q=[0.3])
    b.run(t_end=1.5, rtol=1e-10, atol=1e-12, sample=0.001)
    scene = b.build()
    run = unfurl.simulate(scene)
    theta = run.trajectory["q.h"]
    # The rod reaches the limit at speed v: (1/2) I v^2 = m g d (cos 0.1 - cos 0.3).
    # Past it, I x'' = -k x - tau_g, the weight's moment tau_g = m g d sin 0.1
    # (nearly constant over the limit's small deflection x) pulling it back
    # towards the bottom too, so the deepest x is
    # -tau_g / k + sqrt((tau_g / k)^2 + I v^2 / k).
    inertia, k = 0.02 + 1.5 * 0.16, 1e4
    v = math.sqrt(2 * 1.5 * 9.81 * 0.4 * (math.cos(0.1) - math.cos(0.3)) / inertia)
    static = 1.5 * 9.81 * 0.4 * math.sin(0.1) / k
    deepest = -static + math.sqrt(static**2 + inertia * v**2 / k)
    assert abs((-0.1 - theta.min()) - deepest) < 0.01 * deepest
    assert abs(theta[run.t > 0.5].max() - 0.3) < 1e-6
    assert run.loads.unit("limit_torque.h") == "N m"
    assert run.loads["limit_torque.h"].max() > 0 and run.loads["limit_torque.h"].min() == 0
    assert "limits:" in scene.to_yaml() and "lower: -0.1" in scene.to_yaml()
    with pytest.raises(ValueError, match="lower, upper or both"):
        pendulum_builder().limit("h", stiffness=1)


def test_the_builder_checks_as_a_file_is_checked():
    b = pendulum_builder()
    b.body("arm", parent="rod", mass=0, inertia=[1, 1, 1], joint=dict(name="k", type="revolute"))
    with pytest.raises(unfurl.SceneError, match=r"bodies\[1\] \(arm\).mass"):
        b.build()
    with pytest.raises(unfurl.SceneError, match="nowhere"):
        pendulum_builder().spring("nowhere", stiffness=1, free_position=0)
    with pytest.raises(ValueError, match="joint type 'hinge'"):
        pendulum_builder().body("x", parent="rod", mass=1, inertia=[1, 1, 1], joint=dict(type="hinge"))


def test_an_angle_that_looks_like_degrees_is_warned_about():
    with pytest.warns(UserWarning, match=r"initial.q.j1: -90 rad is more than a turn"):
        unfurl.load("zfold", set={"initial.q.j1": -90})


def test_generated_scenes_are_the_reference_ones_at_three_stages():
    zfold = unfurl.generate("zfold", 3)
    assert zfold.joints == unfurl.load("zfold").joints
    a = unfurl.simulate(zfold, t_end=2)
    b = unfurl.simulate("zfold", t_end=2)
    for j in ("j1", "j2", "j3", "j4"):
        assert abs(a.trajectory["q." + j][-1] - b.trajectory["q." + j][-1]) < 1e-9
    flexible = unfurl.generate("pantograph", 3, flexible=True, snubbers=False)
    assert flexible.joints == unfurl.load("pantograph_flexible").joints
    assert flexible.loops == ["A1", "A2", "A3"]
    assert "limits:" not in flexible.to_yaml()
    # Flexible arrays stand on snubbers like compliant ones.
    assert "limits:" in unfurl.generate("pantograph", 10, flexible=True).to_yaml()
    ten = unfurl.generate("pantograph", 10, compliant=True)
    assert len(ten.bodies) == 22 and ten.loops == []
    assert "limits:" in ten.to_yaml()
    assert "limits:" not in unfurl.generate("pantograph", 10, compliant=True, snubbers=False).to_yaml()


def test_a_bad_generated_scene_is_refused_by_name():
    with pytest.raises(ValueError, match="'kite' is not a generated scene"):
        unfurl.generate("kite", 3)
    with pytest.raises(ValueError, match="from 1 to 1000000"):
        unfurl.generate("pantograph", 0)
    with pytest.raises(TypeError, match="whole number"):
        unfurl.generate("chain", 2.5)
    with pytest.raises(ValueError, match="two different arrays"):
        unfurl.generate("pantograph", 4, compliant=True, flexible=True)
    with pytest.raises(ValueError, match="pantograph only"):
        unfurl.generate("zfold", 4, flexible=True)
