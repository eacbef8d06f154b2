"""Environments by name, as Gymnasium registers them: plantsim.make("plantsim/Dock-v0") builds
the Env registered under that id with its arguments (any given to make() override them) and sets
env.spec; plantsim.make_vec(id, n) the VectorEnv of the same arguments. Gymnasium is not a
Debian package, so plantsim keeps its own registry with Gymnasium's names (register, make,
make_vec, spec, registry); when gymnasium is importable the same ids are also registered with it,
so that gymnasium.make("plantsim/Dock-v0") works (docs/python.md)."""
import dataclasses
import pathlib

_DATA = pathlib.Path(__file__).resolve().parents[3] / "data"


@dataclasses.dataclass(frozen=True)
class EnvSpec:
    """Gymnasium's EnvSpec fields that plantsim's environments use."""
    id: str
    entry_point: str = "plantsim.env:Env"
    kwargs: dict = dataclasses.field(default_factory=dict)
    max_episode_steps: int = None


registry = {}


def register(id, *, entry_point="plantsim.env:Env", kwargs=None, max_episode_steps=None):
    """Registers the environment `id` ("namespace/Name-vN") with its Env arguments."""
    if not isinstance(id, str) or "-v" not in id:
        raise ValueError(f"an environment id is 'namespace/Name-vN', got {id!r}")
    registry[id] = EnvSpec(id, entry_point, dict(kwargs or {}), max_episode_steps)


def spec(id):
    try:
        return registry[id]
    except KeyError:
        raise KeyError(f"no environment {id!r} is registered (registered: {', '.join(sorted(registry))})") from None


def _arguments(s, overrides):
    kwargs = {**s.kwargs, **overrides}
    if s.max_episode_steps is not None and "max_steps" not in overrides:
        kwargs.setdefault("max_steps", s.max_episode_steps)
    return kwargs


def make(id, **overrides):
    """The Env registered as `id`, with `overrides` over its arguments; env.spec says which."""
    from .env import Env
    s = spec(id)
    kwargs = _arguments(s, overrides)
    env = Env(**kwargs)
    env.spec = dataclasses.replace(s, kwargs=kwargs)
    return env


def make_vec(id, num_envs=1, **overrides):
    """The VectorEnv of `num_envs` environments of `id`'s arguments (threads= and the like too)."""
    from .env import VectorEnv
    s = spec(id)
    kwargs = _arguments(s, overrides)
    env = VectorEnv(num_envs, **kwargs)
    env.spec = dataclasses.replace(s, kwargs=kwargs)
    return env


_SMALL_PLANT = str(_DATA / "worlds" / "examples" / "small_plant.json")
register("plantsim/Dock-v0", kwargs={"world": _SMALL_PLANT})
register("plantsim/DockFinite-v0", kwargs={"world": _SMALL_PLANT, "finite": True})
register("plantsim/DockAgent-v0", kwargs={"world": _SMALL_PLANT, "docking": "agent"})
register("plantsim/DockPlants-v0", kwargs={"scenario": str(_DATA / "scenarios" / "plants.yaml")})

try:  # Gymnasium's own registry too, when it is there
    import gymnasium

    for _s in registry.values():
        if _s.id not in gymnasium.registry:
            gymnasium.register(id=_s.id, entry_point=_s.entry_point, kwargs=_s.kwargs,
                               max_episode_steps=_s.max_episode_steps)
except ImportError:
    pass
