"""The step-wise environment against the Gymnasium API's contract and plantsim's own episode:
reset/step signatures and meanings, observations inside their declared spaces, determinism per
seed, truncation, a scenario's episodes by id, the vector API's stacking and next-step autoreset,
pickling, and bad input refused."""
import json
import pickle
import shutil

import numpy as np
import pytest

import plantsim

WORLD = "data/worlds/examples/small_plant.json"


def follow_plantsim(env, seed):
    """Drives with plantsim's own command (info["builtin"]); returns (steps, rewards, obs, info, flags)."""
    obs, info = env.reset(seed=seed)
    rewards = []
    while True:
        obs, reward, terminated, truncated, info = env.step(info["builtin"])
        rewards.append(reward)
        if terminated or truncated:
            return len(rewards), rewards, obs, info, (terminated, truncated)


def test_the_gymnasium_contract_and_plantsims_own_episode(source):
    env = plantsim.Env(source / WORLD)
    obs, info = env.reset(seed=3)
    assert env.observation_space.contains(obs)
    assert set(obs) == set(env.observation_space.keys())
    assert obs["scan"].shape == (360,) and obs["covariance"].shape == (3, 3)
    assert obs["time"] >= 1.0  # the gyro is calibrated at rest first: the agent is asked after it
    assert PHASE(obs) == "travel"
    steps, rewards, last, info, (terminated, truncated) = follow_plantsim(env, 3)
    assert terminated and not truncated
    assert info["status"] == "docked" and info["docked"] and info["failure"] == ""
    # Steered with plantsim's own command the episode is plantsim's own: the same as run().
    run = plantsim.run(str(source / WORLD), seed=3, start="random")
    assert run.status == "docked"
    assert last["time"] == pytest.approx(run.summary["time_s"], abs=0.05)
    assert PHASE(last) == "docked"  # the end's own observation, not the last steered one
    # The default reward: progress of the estimate along the way still to go (to the staging pose
    # and on to the docked pose while travelling, to the docked pose while docking), 0.01 a
    # step, +10 for docking (nothing pressed the bumper).
    docked = plantsim.load_world(source / WORLD).charger[:2]
    def to_go(o):
        if PHASE(o) == "travel":
            return np.linalg.norm(o["pose"][:2] - o["staging"][:2]) + np.linalg.norm(o["staging"][:2] - docked)
        return np.linalg.norm(o["pose"][:2] - docked)
    assert sum(rewards) == pytest.approx(to_go(obs) - to_go(last) - 0.01 * steps + 10, abs=1e-6)
    # plantsim's own approach earns progress all along, docking included (towards the staging
    # pose alone, its docking read as going away: -5.03 over it).
    env.reset(seed=3)
    while True:
        o, reward, terminated, truncated, info = env.step(info["builtin"])
        if PHASE(o) != "travel" and not terminated:
            assert reward > -0.011 - 1e-3, (o["time"], reward)  # at most the time's cost and noise
        if terminated or truncated:
            break
    # The weights are settable; an unknown one or a non-number refused naming it.
    scaled = plantsim.Env(source / WORLD, reward_weights={"per_step": 0.0, "docked": 100})
    _, scaled_rewards, *_ = follow_plantsim(scaled, 3)[:2]
    assert sum(scaled_rewards) == pytest.approx(to_go(obs) - to_go(last) + 100, abs=1e-6)
    with pytest.raises(plantsim.InputError, match="unknown weight 'dock'"):
        plantsim.Env(source / WORLD, reward_weights={"dock": 1})
    with pytest.raises(TypeError, match="docked"):
        plantsim.Env(source / WORLD, reward_weights={"docked": "x"})
    with pytest.raises(plantsim.InputError, match="reset"):
        env.step((0.0, 0.0))


def PHASE(obs):
    return plantsim.PHASES[int(obs["phase"])]


def test_the_same_seed_gives_the_same_episode_and_scans_carry_their_time(source):
    env = plantsim.Env(source / WORLD)
    a = follow_plantsim(env, 7)
    b = follow_plantsim(env, 7)
    assert a[0] == b[0] and a[1] == b[1]
    obs, info = env.reset(seed=7)
    times = []
    for _ in range(30):
        obs, *_ = env.step((0.2, 0.0))
        times.append(float(obs["scan_time"]))
    # The lidar (15 Hz) is slower than the control (30 Hz): a scan is seen twice, with its time.
    assert len(set(times)) < len(times) and all(t <= obs["time"] + 1e-9 for t in times)


def test_max_steps_truncates_and_standing_still_stays_put(source):
    env = plantsim.Env(source / WORLD, start="world", max_steps=40)
    obs, _ = env.reset(seed=1)
    start = obs["pose"].copy()
    for k in range(40):
        obs, reward, terminated, truncated, info = env.step((0.0, 0.0))
        assert not terminated
        assert truncated == (k == 39)
        assert reward == pytest.approx(-0.01, abs=0.02)
    assert np.linalg.norm(obs["pose"][:2] - start[:2]) < 0.05
    with pytest.raises(plantsim.InputError):
        env.step((0.0, 0.0))


def test_a_reward_of_ones_own_and_wheel_speeds(source):
    seen = []

    def reward(obs, info):
        seen.append(info["time"])
        return 42.0

    env = plantsim.Env(source / WORLD, reward=reward, action="wheels")
    env.reset(seed=2)
    _, r, *_ = env.step((0.3, 0.3))
    assert r == 42.0 and len(seen) == 1
    for _ in range(10):  # the drive's soft start (traction.full_grip_accel_mps2) ramps it up
        obs, *_ = env.step((0.3, 0.3))
    assert obs["velocity"][0] > 0.05 and abs(obs["velocity"][1]) < 0.2  # equal wheels: straight on


def test_a_scenarios_episodes_by_id(source, tmp_path, monkeypatch):
    scenario = tmp_path / "s.yaml"
    scenario.write_text(json.dumps({"worlds": [str(source / WORLD)], "seeds": 2,
                                    "faults": {"none": {}, "unmapped": {"unmapped_obstacles": 2}}}))
    env = plantsim.Env(scenario=scenario)
    _, info = env.reset(options={"episode": "small_plant|vg|default|unmapped|2"})
    assert info["episode"] == "small_plant|vg|default|unmapped|2"
    _, info = env.reset(seed=1)
    assert info["episode"] == "small_plant|vg|default|none|2"
    with pytest.raises(plantsim.InputError, match="no episode"):
        env.reset(options={"episode": "small_plant|vg|default|wet|1"})
    with pytest.raises(plantsim.InputError, match="unknown option"):
        env.reset(options={"episodes": 1})
    # A scenario given as a dict, as the docs say (it was refused), its worlds relative to the
    # working folder; seedless resets draw its episodes (worlds and faults) at random.
    as_dict = json.loads(scenario.read_text())
    monkeypatch.chdir(source)
    as_dict["worlds"] = [WORLD]
    drawn = plantsim.Env(scenario=as_dict)
    ids = {drawn.reset()[1]["episode"] for _ in range(24)}
    assert len(ids) >= 3 and ids <= {f"small_plant|vg|default|{f}|{s}" for f in ("none", "unmapped") for s in (1, 2)}
    assert drawn.reset(seed=1)[1]["episode"] == "small_plant|vg|default|none|2"
    assert plantsim.VectorEnv(2, scenario=as_dict, threads=1).reset(seed=0)[1]["episode"][0] == "small_plant|vg|default|none|1"
    # VectorEnv takes the same option, one id (or None: the seed's episode) per environment.
    v = plantsim.VectorEnv(2, scenario=scenario, threads=1)
    _, info = v.reset(seed=[5, 1], options={"episode": ["small_plant|vg|default|unmapped|1", None]})
    assert list(info["episode"]) == ["small_plant|vg|default|unmapped|1", "small_plant|vg|default|none|2"]
    with pytest.raises(plantsim.InputError, match="2 ids"):
        v.reset(options={"episode": ["small_plant|vg|default|none|1"]})
    with pytest.raises(TypeError, match=r"options\['episode'\]\[1\]"):
        v.reset(options={"episode": [None, 3]})


def test_a_vector_envs_own_reward_sees_the_stacked_step_and_gives_0_at_an_autoreset(source):
    n = 3
    seen = []
    def reward(obs, info):
        seen.append((obs["pose"].shape, info["time"].copy()))
        return obs["pose"][:, 0] * 0 + info["steps"]  # one number per environment
    v = plantsim.VectorEnv(n, source / WORLD, max_steps=2, threads=1, reward=reward)
    v.reset(seed=1)
    rewards = [v.step(np.zeros((n, 2)))[1] for _ in range(3)]
    assert seen[0][0] == (n, 3) and len(seen) == 3
    assert list(rewards[0]) == [1.0] * n and list(rewards[1]) == [2.0] * n
    assert list(rewards[2]) == [0.0] * n  # the next episodes' first observations
    bad = plantsim.VectorEnv(n, source / WORLD, threads=1, reward=lambda o, i: 1.0)
    bad.reset(seed=1)
    with pytest.raises(ValueError, match="one number per environment"):
        bad.step(np.zeros((n, 2)))
    with pytest.raises(TypeError, match="callable"):
        plantsim.VectorEnv(n, source / WORLD, reward=3)


def test_vector_env_stacks_and_resets_at_the_next_step(source):
    n = 3
    v = plantsim.VectorEnv(n, source / WORLD, max_steps=5, threads=2)
    obs, info = v.reset(seed=10)
    assert obs["scan"].shape == (n, 360) and obs["pose"].shape == (n, 3)
    assert v.observation_space.contains(obs) and v.single_observation_space["pose"].shape == (3,)
    assert list(info["episode"]) == [f"small_plant|{10 + i}" for i in range(n)]
    # Env's info keys stacked as Gymnasium's vector environments give them, with "_key" masks.
    assert info["episode"].dtype == object and info["_episode"].all() and info["time"].shape == (n,)
    assert info["builtin"].shape == (n, 2) and info["action_used"].all() and len(info["plan"]) == n
    assert not info["_status"].any() and list(info["status"]) == [""] * n
    for k in range(5):
        obs, reward, terminated, truncated, info = v.step(np.zeros((n, 2)))
    assert truncated.all() and not terminated.any()
    assert info["_status"].all() and list(info["truncated_by"]) == ["max_steps"] * n
    assert list(info["status"]) == ["timeout"] * n and not info["docked"].any()
    obs, reward, terminated, truncated, info = v.step(np.zeros((n, 2)))
    assert (reward == 0).all() and not truncated.any()  # the next episodes' first observations
    assert not info["_status"].any()
    # Each autoreset is a reset without a seed: environment i continues its own stream, as an Env
    # reset with seed 10 + i and then without one; alone it gives the same observations.
    single = plantsim.Env(source / WORLD)
    single.reset(seed=10 + 1)
    o, single_info = single.reset()
    assert info["episode"][1] == single_info["episode"]
    assert len(set(info["episode"])) == n and not set(info["episode"]) & {f"small_plant|{10 + i}" for i in range(n)}
    assert np.array_equal(o["pose"], obs["pose"][1]) and np.array_equal(o["scan"], obs["scan"][1], equal_nan=True)
    with pytest.raises(plantsim.InputError, match="shape"):
        v.step(np.zeros((n + 1, 2)))


def test_worlds_and_runs_pickle_and_a_changed_file_is_refused(source, tmp_path):
    path = tmp_path / "w.json"
    shutil.copy(source / WORLD, path)
    w = plantsim.load_world(path, start=(2.0, 7.0, 0.5))
    back = pickle.loads(pickle.dumps(w))
    assert np.array_equal(back.start, w.start) and np.array_equal(back.obstacles, w.obstacles)
    run = plantsim.run(w, seed=1)
    again = pickle.loads(pickle.dumps(run))
    assert again.status == run.status and np.array_equal(again.trajectory, run.trajectory)
    blob = pickle.dumps(w)
    doc = json.loads(path.read_text())
    doc["obstacles"] = doc["obstacles"][1:]
    path.write_text(json.dumps(doc))
    with pytest.raises(plantsim.InputError, match="no longer holds"):
        pickle.loads(blob)


def test_bad_input_is_refused(source):
    with pytest.raises(plantsim.InputError, match="one of them"):
        plantsim.Env()
    with pytest.raises(plantsim.InputError, match="docking"):
        plantsim.Env(source / WORLD, docking="nobody")
    env = plantsim.Env(source / WORLD)
    with pytest.raises(plantsim.InputError, match="reset"):
        env.step((0.0, 0.0))
    env.reset(seed=1)
    with pytest.raises(plantsim.InputError, match="two numbers"):
        env.step((1.0, 2.0, 3.0))
    with pytest.raises(plantsim.InputError, match="non-finite"):
        env.step((float("nan"), 0.0))


def test_spaces_sample_and_contain_as_gymnasium_says(source):
    """Gymnasium's spaces' rules: sample() works for every space (a scalar Box raised) and stays
    inside it, a whole-number space reaches its high end (Box(0, 7) never gave 7), a boolean one
    gives both values (it gave True every time), contains() refuses a dtype that does not cast
    (a float for an int space) and a wrong shape; Dict is a mapping of its spaces."""
    from plantsim.env import Box
    env = plantsim.Env(source / WORLD)
    env.observation_space.seed(5)
    env.action_space.seed(5)
    for _ in range(20):
        sample = env.observation_space.sample()
        assert env.observation_space.contains(sample)
        assert env.action_space.contains(env.action_space.sample())
    assert dict(env.observation_space.items()).keys() == set(env.observation_space)
    assert len(env.observation_space) == len(list(env.observation_space.keys()))
    whole = Box(0, 7, (), np.int64, seed=1)
    assert {int(whole.sample()) for _ in range(400)} == set(range(8))
    flag = Box(0, 1, (), np.bool_, seed=2)
    assert {bool(flag.sample()) for _ in range(60)} == {False, True}
    assert not whole.contains(np.float64(3.0)) and whole.contains(np.int64(3))
    assert not whole.contains(np.int64(8))
    assert not Box(0.0, 1.0, (2,)).contains(np.zeros(3))
    assert Box(0.0, 1.0, (2,)).contains(np.array([0.5, 0.5], dtype=np.float32))
    half = Box(0.0, np.inf, (1000,), seed=3).sample()
    assert np.all(half >= 0) and np.all(np.isfinite(half))


def test_seeds_continue_the_environments_stream_and_never_repeat_an_episode(source):
    # Gymnasium's rule: a seeded reset restarts the stream, a seedless one continues it.
    def ids(env, seeds):
        return [env.reset(seed=s)[1]["episode"] for s in seeds]
    a, b = plantsim.Env(source / WORLD), plantsim.Env(source / WORLD)
    first = ids(a, [5, None, None, None])
    assert first == ids(b, [5, None, None, None])  # reproducible from the seed
    assert first[0] == "small_plant|5" and len(set(first)) == 4
    assert ids(a, [5, None]) == first[:2]  # the seed restarts the stream
    # Never seeded: the machine's entropy (two environments differ), and no repeats.
    fresh = [plantsim.Env(source / WORLD).reset()[1]["episode"] for _ in range(2)]
    assert fresh[0] != fresh[1]
    n = 4
    v = plantsim.VectorEnv(n, source / WORLD, max_steps=1, threads=1)
    seen = []
    for _ in range(7):  # vector wrappers reset without seeds: every episode new
        seen += list(v.reset()[1]["episode"])
    assert len(seen) == 7 * n and len(set(seen)) == 7 * n
    _, info = v.reset(seed=[3, 9, 4, 2**64 - 1])
    assert list(info["episode"]) == ["small_plant|3", "small_plant|9", "small_plant|4", f"small_plant|{2**64 - 1}"]
    _, again = v.reset(seed=np.array([3, 9, 4, 7]))
    assert list(again["episode"][:3]) == list(info["episode"][:3])
    with pytest.raises(plantsim.InputError, match="4 seeds"):
        v.reset(seed=[1, 2, 3])
    with pytest.raises(TypeError, match=r"seed\[1\]"):
        v.reset(seed=[1, 2.5, 3, 4])
    with pytest.raises(plantsim.InputError, match=r"below 2\*\*64"):
        v.reset(seed=2**64 - 2)


def test_plantsims_docking_a_period_a_step_a_first_contact_terminal_and_one_truncation_rule(source):
    # docking="plantsim": its manoeuvre drives a control period a step, the action ignored (and
    # said so); the same episode as docking to the end within one step.
    each, whole = plantsim.Env(source / WORLD), plantsim.Env(source / WORLD, docking="plantsim-whole")
    obs, info = each.reset(seed=3)
    ignored = 0
    while True:
        action = info["builtin"] if info["action_used"] else (9.0, -9.0)  # ignored while it docks
        ignored += not info["action_used"]
        obs, reward, terminated, truncated, info = each.step(action)
        if terminated or truncated:
            break
    w_steps, _, w_last, w_info, _ = follow_plantsim(whole, 3)
    assert info["status"] == w_info["status"] == "docked"
    assert obs["time"] == w_last["time"] and np.array_equal(obs["pose"], w_last["pose"])
    assert ignored > 30 and info["steps"] == w_info["steps"] + ignored
    # A crash is terminal at the first contact: full speed ahead from the world's start (facing a
    # box or a wall), and not with contact="continue".
    def crash(env):
        env.reset(seed=1)
        for k in range(2000):
            obs, reward, terminated, truncated, info = env.step((1.0, 0.0))
            if terminated or truncated:
                return k, reward, terminated, info
        return None
    k, reward, terminated, info = crash(plantsim.Env(source / WORLD, start="world"))
    assert terminated and info["status"] == info["failure"] == "collision" and not info["docked"]
    assert info["collisions"] == 1 and reward < -10
    on = plantsim.Env(source / WORLD, start="world", contact="continue")
    on.reset(seed=1)
    for _ in range(k + 1):
        _, _, terminated, truncated, info = on.step((1.0, 0.0))
    assert not terminated and not truncated  # pressed against it, the episode goes on
    # One truncation rule: max_steps and timeout_s alike give the same keys and no terminal reward.
    for env in (plantsim.Env(source / WORLD, max_steps=20), plantsim.Env(source / WORLD, config={"timeout_s": 3})):
        env.reset(seed=2)
        while True:
            _, reward, terminated, truncated, info = env.step((0.0, 0.0))
            if terminated or truncated:
                break
        assert truncated and not terminated and reward > -1
        assert info["status"] == info["failure"] == "timeout" and not info["docked"]
        assert info["truncated_by"] in ("max_steps", "timeout_s")
    with pytest.raises(plantsim.InputError, match="contact must be"):
        plantsim.Env(source / WORLD, contact="stop")
    with pytest.raises(plantsim.InputError, match="plantsim-whole"):
        plantsim.Env(source / WORLD, docking="builtin")


def test_finite_observations_carry_masks_where_nan_marked_none(source):
    # A noisy lidar drops returns (NaN); finite=True gives its maximum range there, with masks,
    # and the spaces refuse NaN as Gymnasium's do. The same episode either way.
    config = {"lidar": {"dropout_probability": 0.2}}
    raw = plantsim.Env(source / WORLD, config=config)
    fin = plantsim.Env(source / WORLD, config=config, finite=True)
    assert set(fin.observation_space.keys()) == set(raw.observation_space.keys()) | {"scan_valid", "scan_seen"}
    nan_obs = raw.observation_space.sample()
    nan_obs["scan"][0] = np.nan
    assert raw.observation_space.contains(nan_obs)
    (r, _), (f, _) = raw.reset(seed=4), fin.reset(seed=4)
    dropped = 0
    for _ in range(60):
        assert fin.observation_space.contains(f)
        assert not any(np.isnan(v).any() for v in f.values() if np.asarray(v).dtype.kind == "f")
        assert np.array_equal(f["scan_valid"], ~np.isnan(r["scan"]))
        assert np.array_equal(f["scan"][f["scan_valid"]], r["scan"][f["scan_valid"]])
        assert (f["scan"][~f["scan_valid"]] == fin._finite_range).all()
        assert bool(f["charger_seen"]) == (not np.isnan(r["charger"]).any())
        dropped += int((~f["scan_valid"]).sum())
        r, *_ = raw.step(r_action := (0.2, 0.1))
        f, *_ = fin.step(r_action)
    assert dropped > 100  # the case was met
    f["scan"][3] = np.nan
    assert not fin.observation_space.contains(f)
    v = plantsim.VectorEnv(2, source / WORLD, config=config, finite=True, threads=1)
    obs, _ = v.reset(seed=4)
    assert v.observation_space.contains(obs) and obs["scan_valid"].shape == (2, 360)


def test_environments_by_id_as_gymnasium_registers_them(source):
    env = plantsim.make("plantsim/Dock-v0")
    assert env.spec.id == "plantsim/Dock-v0" and env.spec.entry_point == "plantsim.env:Env"
    obs, info = env.reset(seed=3)
    assert info["episode"] == "small_plant|3" and env.observation_space.contains(obs)
    finite = plantsim.make("plantsim/DockFinite-v0", max_steps=5)
    assert "scan_valid" in finite.observation_space.keys() and finite.spec.kwargs["max_steps"] == 5
    finite.reset(seed=1)
    for _ in range(5):
        *_, truncated, info = finite.step((0.0, 0.0))
    assert truncated and info["truncated_by"] == "max_steps"
    v = plantsim.make_vec("plantsim/Dock-v0", 2, threads=1)
    assert v.num_envs == 2 and v.spec.id == "plantsim/Dock-v0"
    plants = plantsim.make("plantsim/DockPlants-v0")
    assert plants.reset(seed=0)[1]["episode"].count("|") == 4  # a scenario's episode id
    plantsim.register("mine/Dock-v1", kwargs={"world": str(source / WORLD), "docking": "agent"}, max_episode_steps=7)
    assert plantsim.make("mine/Dock-v1").spec.kwargs["max_steps"] == 7
    with pytest.raises(KeyError, match="plantsim/Dock-v0"):
        plantsim.make("plantsim/Dok-v0")
    with pytest.raises(ValueError, match="Name-vN"):
        plantsim.register("nameless")


def test_rgb_array_frames_show_the_plant_the_robot_and_its_plan(source):
    env = plantsim.Env(source / WORLD, render_mode="rgb_array", render_size=(480, 300))
    assert env.metadata["render_modes"] == ["rgb_array"] and plantsim.Env(source / WORLD).render() is None
    obs, info = env.reset(seed=3)
    first = env.render()
    assert first.shape == (300, 480, 3) and first.dtype == np.uint8
    for _ in range(200):
        obs, _, terminated, truncated, info = env.step(info["builtin"])
    later = env.render()
    # The plan's colour (Okabe-Ito vermillion) is drawn, and the robot has moved: frames differ.
    vermillion = np.all(np.abs(later.astype(int) - [213, 94, 0]) <= 12, axis=2)
    assert vermillion.sum() > 50
    assert (np.abs(later.astype(int) - first.astype(int)).sum(axis=2) > 60).sum() > 100
    with pytest.raises(ValueError, match="render_mode"):
        plantsim.Env(source / WORLD, render_mode="human")


def one_and_a_half(obs, info):  # a reward the workers import by name (a lambda does not pickle)
    return 1.5


def test_async_vector_env_runs_each_env_in_its_own_process_as_vector_env_does(source):
    world = plantsim.load_world(source / WORLD)  # a World pickles to the workers
    n = 2
    with plantsim.AsyncVectorEnv(n, world=world, max_steps=3, reward=one_and_a_half) as envs:
        obs, info = envs.reset(seed=10)
        assert obs["scan"].shape == (n, 360) and list(info["episode"]) == ["small_plant|10", "small_plant|11"]
        assert envs.observation_space.contains(obs)
        for _ in range(3):
            obs, rewards, terminated, truncated, info = envs.step(np.zeros((n, 2)))
        assert truncated.all() and list(rewards) == [1.5, 1.5] and info["_status"].all()
        assert list(info["truncated_by"]) == ["max_steps"] * n
        # Next-step autoreset, each environment continuing its own stream as an Env does.
        obs, rewards, terminated, truncated, info = envs.step(np.zeros((n, 2)))
        assert list(rewards) == [0.0, 0.0] and not truncated.any()
        single = plantsim.Env(source / WORLD)
        single.reset(seed=11)
        o, single_info = single.reset()
        assert info["episode"][1] == single_info["episode"] and np.array_equal(o["pose"], obs["pose"][1])
    with pytest.raises(plantsim.InputError, match="environment 0: .*planner"):
        plantsim.AsyncVectorEnv(1, world=str(source / WORLD), planner="nope")
