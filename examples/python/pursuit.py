"""A plain pure pursuit written in Python, to steer plantsim's robot in place of its own path
following: the carrot is the point a lookahead along the plan beyond the closest point, the arc
through it is driven at a fixed speed, and a carrot behind the robot is faced in place first.
Sharp corners of the plan are driven to, not cut. It sees only the observation (the estimated
pose and plantsim's plan), never the truth."""
import math

import numpy as np


def closest_on_plan(plan, x, y):
    """(segment index, fraction along it) of the plan point closest to (x, y)."""
    a, b = plan[:-1], plan[1:]
    ab = b - a
    t = np.clip(((x - a[:, 0]) * ab[:, 0] + (y - a[:, 1]) * ab[:, 1]) / np.maximum((ab * ab).sum(axis=1), 1e-12), 0, 1)
    d = np.hypot(a[:, 0] + t * ab[:, 0] - x, a[:, 1] + t * ab[:, 1] - y)
    i = int(np.argmin(d))
    return i, float(t[i])


def turn_at(plan, j):
    """The heading change at plan vertex j (0 at the ends)."""
    if j <= 0 or j >= len(plan) - 1:
        return 0.0
    a, b = plan[j] - plan[j - 1], plan[j + 1] - plan[j]
    return abs(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]))


def carrot_on_plan(plan, x, y, lookahead, sharp=0.5, release=0.15):
    """A lookahead along the plan, but never round a sharp corner: the plan hugs the inflated
    obstacles there, and an arc across the corner would clip them."""
    i, t = closest_on_plan(plan, x, y)
    point, left = plan[i] + t * (plan[i + 1] - plan[i]), lookahead
    for j in range(i + 1, len(plan)):
        step = math.hypot(*(plan[j] - point))
        if step >= left:
            return point + (plan[j] - point) * (left / step)
        if turn_at(plan, j) > sharp and math.hypot(plan[j][0] - x, plan[j][1] - y) > release:
            return plan[j]
        left -= step
        point = plan[j]
    return plan[-1]


def something_ahead(obs, x, y, yaw, reach, half_width):
    """True when a tracked obstacle (a person, an unmapped box) lies in the strip ahead."""
    if len(obs.obstacles) == 0:
        return False
    boxes = obs.obstacles
    # The box's point closest to the robot, in the robot frame.
    px = np.clip(x, boxes[:, 0], boxes[:, 2]) - x
    py = np.clip(y, boxes[:, 1], boxes[:, 3]) - y
    ahead = math.cos(yaw) * px + math.sin(yaw) * py
    side = -math.sin(yaw) * px + math.cos(yaw) * py
    return bool(np.any((ahead > -0.05) & (ahead < reach) & (np.abs(side) < half_width)))


def make_pursuit(lookahead=0.6, speed=0.5, turn_speed=0.8, stop_reach=1.2, stop_half_width=0.55):
    """A controller f(observation) -> (v, omega) with these gains; it stops while a tracked
    obstacle is in the strip ahead (stop_reach long, 2 * stop_half_width wide)."""
    def pursuit(obs):
        x, y, yaw = obs.pose
        plan = obs.plan
        if len(plan) < 2:
            return None  # nothing to follow: let plantsim command
        if something_ahead(obs, x, y, yaw, stop_reach, stop_half_width):
            return 0.0, 0.0
        cx, cy = carrot_on_plan(plan, x, y, lookahead) - (x, y)
        lx = math.cos(yaw) * cx + math.sin(yaw) * cy
        ly = -math.sin(yaw) * cx + math.cos(yaw) * cy
        d2 = lx * lx + ly * ly
        if d2 < 1e-9:
            return 0.0, 0.0
        if lx < 0.3 * math.sqrt(d2):  # the carrot is beside or behind: turn towards it in place
            return 0.0, math.copysign(turn_speed, ly)
        return speed, 2.0 * speed * ly / d2
    pursuit.__name__ = "python_pursuit"
    return pursuit
