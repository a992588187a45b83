#!/usr/bin/env python3
"""Prints the "colliders" of samples/grass_render/scenes/park-walker.json: a walker as two
capsules (its legs), hip to foot, crossing the park along +x. Each foot is planted for half
of its 1 s stride and swings forward over the other half, lifted 0.15 m at mid-swing; the
hips move at a constant walking speed. Rerun and paste to change the walk.
"""
import json

SPEED = 1.3        # m/s
START = (3.2, 8.0)  # x, z of the hips at t = 0
HIP, LIFT, RADIUS, HALF_WIDTH = 0.9, 0.15, 0.08, 0.12
DURATION = 4.0


def leg(side, phase):
    z = START[1] + side * HALF_WIDTH
    keys = []
    k = -1
    while k < DURATION + 1:
        t0 = k + phase
        plant = START[0] + SPEED * (t0 + 0.25)          # under the hip at mid-stance
        keys.append([t0, plant, RADIUS, z])
        keys.append([t0 + 0.5, plant, RADIUS, z])
        keys.append([t0 + 0.75, plant + SPEED * 0.5, RADIUS + LIFT, z])
        k += 1
    keys = [[round(v, 4) for v in key] for key in keys if -1.0 <= key[0] <= DURATION + 1]
    hip = {"from": [START[0], HIP, z], "to": [START[0] + SPEED * (DURATION + 1), HIP, z], "speed": SPEED}
    return {"shape": "capsule", "radius": RADIUS, "centre": hip, "end": {"keyframes": keys}}


print(json.dumps([leg(-1, 0.0), leg(+1, 0.5)], separators=(", ", ": ")))
