"""Nav2 parameter files as plantsim configs: the documented examples written as fixtures."""
import json
import subprocess

import pytest

import plantsim


def test_regulated_pure_pursuit_readme(source):
    im = plantsim.nav2_import(str(source / "tests/fixtures/nav2/rpp_readme.yaml"))
    t = im["config"]["tracking"]
    assert t["max_linear_speed_mps"] == 0.5
    assert t["lookahead_min_m"] == t["lookahead_max_m"] == 0.6  # use_velocity_scaled_lookahead_dist: false
    assert t["rotate_in_place_threshold_rad"] == 0.785 and t["regulated_min_radius_m"] == 0.9
    assert im["config"]["step"]["control_period_steps"] == 3  # 20 Hz of 60 Hz physics
    assert im["config"]["traction"]["max_angular_accel_radps2"] == 3.2
    why = {p["nav2"].split(".")[-1]: p["note"] for p in im["not_mapped"]}
    assert "costmap" in why["use_cost_regulated_linear_velocity_scaling"]
    assert "allow_reversing" in why and "transform_tolerance" in why
    assert not im["plugins_not_implemented"]


def test_nav2_bringups_mppi_file_drives_mppi(source):
    im = plantsim.nav2_import(str(source / "tests/fixtures/nav2/nav2_bringup_mppi.yaml"))
    assert not im["plugins_not_implemented"]
    c = im["config"]
    assert c["local_controller"] == "mppi"
    assert c["mppi"]["vx_max"] == 0.5 and c["mppi"]["vx_min"] == -0.35 and c["mppi"]["temperature"] == 0.3
    assert c["mppi"]["batch_size"] == 2000 and isinstance(c["mppi"]["batch_size"], int)
    assert c["mppi"]["goal_tolerance_m"] == 0.25  # the goal checker serves the controller that drives
    why = {p["nav2"].split(".")[-1]: p["note"] for p in im["not_mapped"]}
    assert "eight critics" in why["critics"] and "motion_model" in why
    # The imported file drives MPPI to the dock.
    r = plantsim.run(str(source / "data/worlds/examples/corridor_crossing.json"), config=c)
    assert r.docked and r.summary["collisions"] == 0
    fields = {p["nav2"]: p for p in im["world_fields"]}
    assert fields["local_costmap.robot_radius"]["plantsim"] == "world file: robot.radius_m"
    assert "inflation_radius" in " ".join(fields)


def test_opennav_docking(source):
    im = plantsim.nav2_import(str(source / "tests/fixtures/nav2/opennav_docking.yaml"))
    c = im["config"]
    assert c["docking"]["approach_speed_mps"] == 0.15 and c["docking"]["max_retries"] == 3
    assert c["tolerance"]["position_m"] == 0.05 and c["detection"]["enabled"] is True
    assert any(p["plantsim"] == "world file: charger.staging_distance_m" for p in im["world_fields"])


def test_the_imported_config_drives_and_the_command_writes_it(source, binary, tmp_path):
    out = tmp_path / "rpp.json"
    cli = subprocess.run([binary, "nav2-import", str(source / "tests/fixtures/nav2/rpp_readme.yaml"), "--out", str(out)],
                         capture_output=True, text=True)
    assert cli.returncode == 0 and "mapped (13)" in cli.stderr and "not mapped" in cli.stderr
    config = json.loads(out.read_text())
    assert config == plantsim.nav2_import(str(source / "tests/fixtures/nav2/rpp_readme.yaml"))["config"]
    r = plantsim.run(source / "data/worlds/examples/corridor_crossing.json", config=str(out))
    assert r.docked, r.summary["failure"]


def test_not_a_nav2_file(tmp_path, binary):
    f = tmp_path / "x.yaml"
    f.write_text("just: [a, list]\n")
    with pytest.raises(plantsim.InputError, match="no controller_server"):
        plantsim.nav2_import(str(f))
    f.write_text("controller_server:\n  ros__parameters:\n    FollowPath:\n      plugin: nav2_regulated_pure_pursuit_controller::RegulatedPurePursuitController\n      desired_linear_vel: fast\n")
    cli = subprocess.run([binary, "nav2-import", str(f)], capture_output=True, text=True)
    assert cli.returncode == 2 and "desired_linear_vel" in cli.stderr


def test_todays_names_the_smoothers_caps_and_every_section_listed(source):
    # Issue 50: RPP's max_linear_vel (not desired_linear_vel) is the cruise speed, max_angular_vel
    # and the smoother's theta cap bound the turn rate (the lower wins), and sections plantsim
    # does not model are listed parameter by parameter, not skipped.
    im = plantsim.nav2_import(str(source / "tests/fixtures/nav2/today_rpp_smoother.yaml"))
    t = im["config"]["tracking"]
    assert t["max_linear_speed_mps"] == 0.45
    assert t["max_angular_speed_radps"] == 1.0
    why = {p["nav2"]: p["note"] for p in im["not_mapped"]}
    assert "superseded by max_linear_vel" in why["controller_server.FollowPath.desired_linear_vel"]
    assert "EKF" in why["amcl.alpha1"] and "amcl.max_particles" in why
    assert "bt_navigator.global_frame" in why
    assert "velocity_smoother.max_decel" in why
    fields = {p["nav2"]: p["plantsim"] for p in im["world_fields"]}
    assert fields["velocity_smoother.max_velocity"] == "world file: robot.max_speed_mps"
    assert fields["velocity_smoother.max_accel"] == "world file: robot.max_accel_mps2"
    mapped = {p["nav2"]: p["note"] for p in im["mapped"]}
    assert "meaning changed" in mapped["controller_server.FollowPath.max_angular_accel"]


def test_a_dwb_file_maps_its_kinematics_and_critics_scales(tmp_path):
    f = tmp_path / "dwb.yaml"
    f.write_text("""controller_server:
  ros__parameters:
    controller_plugins: ["FollowPath"]
    FollowPath:
      plugin: "dwb_core::DWBLocalPlanner"
      max_vel_x: 0.3
      vx_samples: 25
      sim_time: 1.5
      critics: ["RotateToGoal", "Oscillation", "BaseObstacle", "GoalAlign", "PathAlign", "PathDist", "GoalDist"]
      BaseObstacle.scale: 0.02
      PathAlign:
        scale: 30.0
        forward_point_distance: 0.3
      RotateToGoal:
        scale: 31.0
        slowing_factor: 4.0
      trans_stopped_velocity: 0.25
""")
    im = plantsim.nav2_import(str(f))
    c = im["config"]
    assert c["local_controller"] == "dwb" and not im["plugins_not_implemented"]
    assert c["dwb"]["max_vel_x"] == 0.3 and c["dwb"]["vx_samples"] == 25 and c["dwb"]["sim_time"] == 1.5
    assert c["dwb"]["path_align_scale"] == 30.0 and c["dwb"]["forward_point_distance"] == 0.3
    assert c["dwb"]["rotate_to_goal_scale"] == 31.0 and c["dwb"]["slowing_factor"] == 4.0
    notes = {p["nav2"]: p["note"] for p in im["not_mapped"]}
    assert "DWB does not have" in notes["controller_server.FollowPath.trans_stopped_velocity"]
    # A flat key, as nav2_bringup writes them (BaseObstacle.scale), maps as a block's does.
    assert c["dwb"]["base_obstacle_scale"] == 0.02
