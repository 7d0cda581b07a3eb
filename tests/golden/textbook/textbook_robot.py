#!/usr/bin/env python3
"""The textbook robot (Poole & Mackworth, "Artificial Intelligence", chapter 2: agentEnv.py,
agentMiddle.py, agentTop.py), restated as one small program. It writes the reference traces that
the scenario tests compare Layerbot's basic controller against, tick by tick.

Usage: python3 textbook_robot.py > office.csv   (or: trap > trap.csv)
Output: tick,x,y,heading,whisker,crashed ; tick 0 is the initial state.
"""
import math
import sys


def line_segments_intersect(linea, lineb):
    """The textbook's test: parallel segments never intersect; end points count."""
    ((x0a, y0a), (x1a, y1a)) = linea
    ((x0b, y0b), (x1b, y1b)) = lineb
    da, db = x1a - x0a, x1b - x0b
    ea, eb = y1a - y0a, y1b - y0b
    denom = db * ea - eb * da
    if denom == 0:
        return False
    cb = (da * (y0b - y0a) - ea * (x0b - x0a)) / denom
    if cb < 0 or cb > 1:
        return False
    ca = (db * (y0b - y0a) - eb * (x0b - x0a)) / denom
    return 0 <= ca <= 1


class Body:
    def __init__(self, walls, x, y, heading):
        self.walls = walls
        self.x, self.y, self.dir = x, y, heading
        self.turning_angle = 18
        self.whisker_length = 6
        self.whisker_angle = 30
        self.crashed = False
        self.rows = []
        self.sense()
        self.record()

    def sense(self):
        d = (self.dir - self.whisker_angle) * math.pi / 180
        whisker = ((self.x, self.y), (self.x + self.whisker_length * math.cos(d), self.y + self.whisker_length * math.sin(d)))
        self.whisker = any(line_segments_intersect(whisker, w) for w in self.walls)

    def record(self):
        self.rows.append((self.x, self.y, self.dir, self.whisker, self.crashed))

    def do(self, steer):
        if self.crashed:
            return
        self.dir = (self.dir + {'left': 1, 'straight': 0, 'right': -1}[steer] * self.turning_angle + 360) % 360
        nx = self.x + math.cos(self.dir * math.pi / 180)
        ny = self.y + math.sin(self.dir * math.pi / 180)
        if any(line_segments_intersect(((self.x, self.y), (nx, ny)), w) for w in self.walls):
            self.crashed = True  # Layerbot's robot stays where it was and moves no more
        else:
            self.x, self.y = nx, ny
        self.sense()
        self.record()


def steer(body, gx, gy, straight_angle=11):
    if body.whisker:
        return 'left'
    rx, ry = body.x, body.y
    goal_dir = math.acos((gx - rx) / math.sqrt((gx - rx) * (gx - rx) + (gy - ry) * (gy - ry))) * 180 / math.pi
    if ry > gy:
        goal_dir = -goal_dir
    goal_from_rob = (goal_dir - body.dir + 540) % 360 - 180
    if goal_from_rob > straight_angle:
        return 'left'
    if goal_from_rob < -straight_angle:
        return 'right'
    return 'straight'


def close_enough(body, gx, gy, threshold=2):
    return (gx - body.x) ** 2 + (gy - body.y) ** 2 <= threshold ** 2


def visit(body, locations, plan, timeout=200, max_ticks=2000):
    for name in plan:
        gx, gy = locations[name]
        remaining = timeout
        while not close_enough(body, gx, gy) and remaining != 0 and not body.crashed and len(body.rows) <= max_ticks:
            body.do(steer(body, gx, gy))
            remaining -= 1
        if body.crashed:
            return


WORLDS = {
    'office': (
        [((20, 0), (30, 20)), ((70, -5), (70, 25))],
        {'mail': (-5, 10), 'o103': (50, 10), 'o109': (100, 10), 'storage': (101, 51)},
        ['o109', 'storage', 'o109', 'o103'],
        (0, 0, 90),
    ),
    'trap': (
        [((10, -21), (10, 0)), ((10, 10), (10, 31)), ((30, -10), (30, 0)), ((30, 10), (30, 20)), ((50, -21), (50, 31)),
         ((10, -21), (50, -21)), ((10, 0), (30, 0)), ((10, 10), (30, 10)), ((10, 31), (50, 31))],
        {'goal': (71, 0)},
        ['goal'],
        (-1, 0, 90),
    ),
}

if __name__ == '__main__':
    walls, locations, plan, (x, y, h) = WORLDS[sys.argv[1] if len(sys.argv) > 1 else 'office']
    body = Body(walls, x, y, h)
    visit(body, locations, plan)
    print('tick,x,y,heading,whisker,crashed')
    for t, (x, y, d, w, c) in enumerate(body.rows):
        print(f'{t},{x!r},{y!r},{d!r},{str(w).lower()},{str(c).lower()}')
