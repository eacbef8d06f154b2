# Typing stubs for the extension (help() on each function gives the whole call).
from typing import Any, Callable, Optional, Sequence, Tuple, Union
import os
import numpy as np

PathLike = Union[str, os.PathLike]
Command = Optional[Tuple[float, float]]

PHASES: Tuple[str, ...]

class InputError(ValueError): ...

class World:
    name: str
    source: str
    floor: np.ndarray
    obstacles: np.ndarray
    unmapped: np.ndarray
    start: np.ndarray
    charger: np.ndarray
    staging: np.ndarray
    robot_radius: float
    wheel_base: float
    max_speed: float

class Plan:
    planner: str
    status: str
    note: str
    length: float
    path: np.ndarray
    drive_path: np.ndarray
    stats: dict

class Observation:
    time: float
    pose: np.ndarray
    covariance: np.ndarray
    position_sigma: float
    health: str
    velocity: Tuple[float, float]
    scan_ranges: np.ndarray
    scan_angles: np.ndarray
    scan_max_range: float
    scan_time: float
    plan: np.ndarray
    staging: np.ndarray
    obstacles: np.ndarray
    charger: Optional[np.ndarray]
    charging: bool
    bumper: bool
    phase: str
    builtin: Tuple[float, float]

class Run:
    summary: dict
    trajectory: np.ndarray
    columns: list
    status: str
    docked: bool

def load_world(path: PathLike, *, start: Optional[Sequence[float]] = ..., charger: Optional[Sequence[float]] = ...,
               scen: str = ..., query: int = ...) -> World: ...
def planners() -> list: ...
def plan(world: Union[World, PathLike], planner: str = ..., *, start: Optional[Sequence[float]] = ...,
         goal: Union[str, Sequence[float]] = ...) -> Plan: ...
def run(world: Union[World, PathLike], *, seed: int = ..., config: Union[None, dict, PathLike] = ...,
        controller: Optional[Callable[[Observation], Command]] = ...,
        docking: Optional[Callable[[Observation], Command]] = ..., planner: str = ...,
        out: Optional[PathLike] = ..., controller_name: str = ...) -> Run: ...
def nav2_import(path: str) -> dict: ...
def load_plugin(path: str) -> dict: ...
def components() -> dict: ...

class _Env:
    limits: Tuple[float, float, int, float]
    def __init__(self, world: Any, scenario: Any, config: Any, planner: str, start: Any, docking: str, action: str,
                 reward: Any, max_steps: int) -> None: ...
    def reset(self, seed: Optional[int], options: Optional[dict]) -> tuple: ...
    def step(self, action: Sequence[float]) -> tuple: ...

class _VectorEnv:
    limits: Tuple[float, float, int, float]
    def __init__(self, n: int, world: Any, scenario: Any, config: Any, planner: str, start: Any, docking: str,
                 action: str, max_steps: int, threads: int) -> None: ...
    def reset(self, seed: Optional[int]) -> tuple: ...
    def step(self, actions: np.ndarray) -> tuple: ...
