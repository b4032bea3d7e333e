#!/usr/bin/env python3
"""Writes scenes/reference/: the scenes of `stepwise bench engine` whose right answer is known,
each NAME.json with its sidecar NAME.expect.json (docs/engine_bench.md). The closed forms are
computed here, once, so a sidecar's expected value and its formula cannot disagree; re-run it
after changing a scene:  python3 bench/engine/make_reference_scenes.py"""
import json
import math
import os

G = 9.81
OUT = os.path.join(os.path.dirname(__file__), "..", "..", "scenes", "reference")
GROUND = {"name": "ground", "type": "static", "shape": {"box": {"half_extents": [50, 0.5, 50]}},
          "position": [0, -0.5, 0]}


def r(x):
    return round(x, 6)


def write(name, description, bodies, checks, seconds, group, settings=None, joints=None, generator=None):
    scene = {"format": "stepwise-scene", "version": 1, "name": name, "description": description}
    if settings:
        scene["settings"] = settings
    scene["bodies"] = bodies
    if joints:
        scene["joints"] = joints
    if generator:
        scene["generator"] = generator
    expect = {"format": "stepwise-expect", "version": 1, "group": group, "seconds": seconds, "checks": checks}
    with open(os.path.join(OUT, name + ".json"), "w") as f:
        f.write(dump_one_item_a_line(scene))
    with open(os.path.join(OUT, name + ".expect.json"), "w") as f:
        json.dump(expect, f, indent=2)
        f.write("\n")


def dump_one_item_a_line(scene):
    """The scene as JSON with one body or joint a line: a 820-box pyramid stays readable."""
    lines = []
    for key, value in scene.items():
        if isinstance(value, list):
            items = ",\n    ".join(json.dumps(item) for item in value)
            lines.append(f'  "{key}": [\n    {items}\n  ]')
        else:
            lines.append(f'  "{key}": {json.dumps(value)}')
    return "{\n" + ",\n".join(lines) + "\n}\n"


def sphere(name, pos, radius, **extra):
    return dict({"name": name, "shape": {"sphere": {"radius": radius}}, "position": pos}, **extra)


def box(name, pos, half, **extra):
    return dict({"name": name, "shape": {"box": {"half_extents": half}}, "position": pos}, **extra)


def quat_z(angle):
    return [0, 0, r(math.sin(angle / 2)), r(math.cos(angle / 2))]


# Projectile: no contact, gravity only.
write("projectile", "A ball thrown at 10 m/s, 45 degrees up, for 1 s in the air: the exact parabola.",
      [sphere("ball", [0, 10, 0], 0.1, velocity=[7.071068, 7.071068, 0], mass=0.5)],
      [{"metric": "closed_form_position", "body": "ball", "tolerance": 0.1,
        "why": "the ball's radius: a throw lands where it was aimed to within the ball's own size"}],
      1.0, "closed-form")

# Free spin about a principal axis of a brick: torque-free, the angular velocity stays constant.
write("free-spin", "A brick spinning at 10 rad/s about its longest principal axis, no gravity: it turns at a constant rate.",
      [box("brick", [0, 0, 0], [0.1, 0.3, 0.5], angular_velocity=[10, 0, 0], mass=2)],
      [{"metric": "closed_form_rotation", "body": "brick", "tolerance": math.radians(1),
        "why": "one degree after 20 rad of turning: a mark on a spinning wheel where the eye expects it"}],
      2.0, "closed-form", settings={"gravity": [0, 0, 0]})

# Bouncing ball: rebound apex e^2 h.
e, h, rad = 0.8, 1.0, 0.1
apex = rad + e * e * h
write("bouncing-ball", f"A ball with restitution {e} dropped from {h} m (its lowest point): it rebounds to e^2 h = {e*e*h:.2f} m.",
      [GROUND | {"restitution": e}, sphere("ball", [0, rad + h, 0], rad, mass=0.5, restitution=e)],
      [{"metric": "bounce_apex", "body": "ball", "expected": r(apex), "tolerance": r(0.05 * e * e * h),
        "why": "5% of the rebound height: a measured restitution coefficient is good to about 0.02, which moves e^2 h by 5%"}],
      1.5, "contact")

# Sliding to rolling: a sphere thrown along the ground without spin rolls on at 5/7 of its speed.
v0, mu = 3.0, 0.3
write("slide-to-roll", f"A ball sliding at {v0} m/s without spin on ground with friction {mu}: friction turns it to rolling at 5/7 v = {5*v0/7:.3f} m/s after 2v/(7 mu g) = {2*v0/(7*mu*G):.2f} s.",
      [GROUND | {"friction": mu}, sphere("ball", [0, 0.1, 0], 0.1, velocity=[v0, 0, 0], mass=1, friction=mu)],
      [{"metric": "final_speed", "body": "ball", "expected": r(5 * v0 / 7), "tolerance": r(0.01 * v0),
        "why": "1% of the throw: 5/7 v holds for any friction of a uniform ball, so only the solver's error moves it"}],
      1.5, "contact")

# Block on a ramp: sticks when mu > tan(angle), slides with a = g (sin - mu cos) otherwise.
angle = math.radians(30)
ramp_half = [3, 0.1, 1]
def ramp_and_block(tag, mu, z):
    n = [-math.sin(angle), math.cos(angle), 0]  # the ramp's top face normal (ramp turned by +angle about z)
    centre = [0, 2, z]
    top = [centre[i] + ramp_half[1] * n[i] for i in range(3)]
    block_half = 0.2
    along = [math.cos(angle), math.sin(angle), 0]
    pos = [top[i] + block_half * n[i] + 1.0 * along[i] for i in range(3)]
    return [{"name": "ramp_" + tag, "type": "static", "shape": {"box": {"half_extents": ramp_half}},
             "position": centre, "orientation": quat_z(angle), "friction": mu},
            box("block_" + tag, [r(p) for p in pos], [block_half] * 3, orientation=quat_z(angle), mass=1, friction=mu)]
t_ramp = 1.0
slide = 0.5 * G * (math.sin(angle) - 0.3 * math.cos(angle)) * t_ramp ** 2
write("ramp", f"Two blocks on 30 degree ramps (atan mu against 30 degrees): with mu = 0.8 (38.7 degrees) it sticks, with mu = 0.3 (16.7 degrees) it slides g (sin - mu cos) t^2 / 2 = {slide:.3f} m in {t_ramp} s.",
      ramp_and_block("sticks", 0.8, -2) + ramp_and_block("slides", 0.3, 2),
      [{"metric": "displacement", "body": "block_sticks", "expected": 0, "tolerance": 0.01,
        "why": "1 cm in a second: a block that should stick must not be seen creeping"},
       {"metric": "displacement", "body": "block_slides", "expected": r(slide), "tolerance": 0.04,
        "why": "a friction coefficient known to 0.01 moves the distance by g cos(30) t^2 / 2 x 0.01 = 4 cm"}],
      t_ramp, "contact")

# Newton's cradle, in free space: five touching balls, the first arriving at 2 m/s (above the
# default restitution threshold of 1 m/s, so every collision of the row is meant to bounce).
m_ball = 1000 * 4 / 3 * math.pi * 0.1 ** 3
v_in = 2.0
balls = [sphere("ball0", [-0.3, 0, 0], 0.1, velocity=[v_in, 0, 0], restitution=1, friction=0)]
balls += [sphere(f"ball{i}", [0.2 * i, 0, 0], 0.1, restitution=1, friction=0) for i in range(1, 5)]
write("newtons-cradle", f"Five balls in a row, no gravity, restitution 1, the first arriving at {v_in:g} m/s: the last leaves at {v_in:g} m/s and the others stay still; momentum and energy are kept.",
      balls,
      [{"metric": "final_speed", "body": "ball4", "expected": v_in, "tolerance": r(0.05 * v_in),
        "why": "5%: a real cradle's steel balls (e about 0.95) send the last ball off at about 95% of the first's speed"},
       {"metric": "final_speed", "body": "ball0", "expected": 0.0, "tolerance": r(0.05 * v_in),
        "why": "the same 5%: the first ball stops; a solver that spreads the momentum over all five moves it on"},
       {"metric": "momentum", "tolerance": r(0.01 * m_ball * v_in),
        "why": "1% of the momentum brought in (kg m/s): nothing outside the balls pushes them"},
       {"metric": "energy_change", "tolerance": 0.1,
        "why": "10% of the energy, what the 5% on the speeds allows (energy goes with their squares)"}],
      1.0, "contact", settings={"gravity": [0, 0, 0]})

# Hinge pendulum: a ball on a massless rod, released from 10 degrees.
L, rb, theta0 = 1.0, 0.05, math.radians(10)
m_bob = 1.0
inertia = 0.4 * m_bob * rb * rb + m_bob * L * L
period = 2 * math.pi * math.sqrt(inertia / (m_bob * G * L)) * (1 + theta0 ** 2 / 16 + 11 * theta0 ** 4 / 3072)
pivot = [0, 3, 0]
bob = [pivot[0] + L * math.sin(theta0), pivot[1] - L * math.cos(theta0), 0]
write("hinge-pendulum", f"A 1 kg ball hanging 1 m below a hinge, released from 10 degrees: period 2 pi sqrt(I / (m g L)) with the amplitude correction, {period:.4f} s.",
      [box("pivot", pivot, [0.05, 0.05, 0.05], type="static"),
       sphere("bob", [r(x) for x in bob], rb, mass=m_bob)],
      [{"metric": "period", "body": "bob", "center": pivot[0], "expected": r(period), "tolerance": r(0.01 * period),
        "why": "1% of the period: a pendulum clock 1% off is visibly out of step after 50 swings"}],
      6.0, "joint",
      joints=[{"type": "hinge", "a": "pivot", "b": "bob", "axis": [0, 0, 1],
               "anchor_b": [r(pivot[i] - bob[i]) for i in range(3)]}])

# Hanging chain: 20 links released horizontally; it swings down and must not stretch.
links, half = 20, 0.05
bodies = [box("anchor", [0, 4, 0], [0.05, 0.05, 0.05], type="static")]
joints = []
for i in range(links):
    bodies.append(box(f"link{i}", [r(0.05 + half + 2 * half * i), 4, 0], [half, 0.02, 0.02], mass=0.1))
    joints.append({"type": "ball_socket", "a": "anchor" if i == 0 else f"link{i-1}", "b": f"link{i}",
                   "anchor_a": [0.05, 0, 0] if i == 0 else [half, 0, 0], "anchor_b": [-half, 0, 0]})
length = 0.05 + 2 * half * links
write("hanging-chain", f"A chain of {links} links, {length:.2f} m long, released horizontally from a fixed anchor: it swings down and must not stretch.",
      bodies,
      [{"metric": "max_distance", "body": f"link{links-1}", "point": [half, 0, 0], "to": [0, 4, 0],
        "expected": r(length), "tolerance": r(0.01 * length),
        "why": "1% of the chain's length: a chain that lengthens by more is seen to stretch like rubber"}],
      3.0, "joint", joints=joints)

# Stacks: drift (sideways) and sag (downwards). Boxes of 1 m.
def stand_checks(layers, sag_note):
    return [{"metric": "drift", "tolerance": 0.01,
             "why": "1 cm, 1% of a box: a stack or pyramid that stands does not walk (the issue's target)"},
            {"metric": "sag", "tolerance": r(0.01 * layers),
             "why": f"1 cm per contact layer ({sag_note}): an overlap of 1% of a box is where boxes still look like they touch"}]

write("stack-16", "Sixteen 1 m boxes in a column: it stands for 5 s without walking or sinking.",
      [GROUND] + [box(f"box{i}", [0, 0.5 + i, 0], [0.5, 0.5, 0.5], mass=1) for i in range(16)],
      stand_checks(16, "16 layers"), 5.0, "stack")


def pyramid(rows):
    out = [GROUND]
    for row in range(rows):
        for i in range(rows - row):
            out.append(box(f"r{row}b{i}", [r(-0.5 * (rows - row - 1) * 1.05 + 1.05 * i), 0.5 + row, 0], [0.5, 0.5, 0.5], mass=1))
    return out


for rows in (20, 40):
    write(f"pyramid-{rows}", f"A pyramid of {rows} rows of 1 m boxes ({rows*(rows+1)//2} boxes, 5 cm apart in a row): it stands for 5 s.",
          pyramid(rows), stand_checks(rows, f"{rows} layers"), 5.0, "stack")

write("mass-ratio-tower", "Four 1 m boxes of 1, 10, 100 and 1000 kg, the heaviest on top: a 1:1000 mass ratio that sequential solvers struggle to hold.",
      [GROUND] + [box(f"box{i}", [0, 0.5 + i, 0], [0.5, 0.5, 0.5], mass=10 ** i) for i in range(4)],
      stand_checks(4, "4 layers"), 5.0, "stack")

write("bullet-wall", "A 5 cm ball at 200 m/s (3.3 m a frame) at a 2 cm thick wall: it must stop at the wall, not pass through.",
      [box("wall", [5, 0, 0], [0.01, 1, 1], type="static"),
       sphere("bullet", [0, 0, 0], 0.05, velocity=[200, 0, 0], mass=0.01)],
      [{"metric": "max_coordinate", "body": "bullet", "axis": 0, "limit": r(4.99 - 0.05), "tolerance": 0.01,
        "why": "1 cm into a 2 cm wall: deeper and the ball is through it (tunnelled)"}],
      0.5, "contact", settings={"gravity": [0, 0, 0]})

# The stress generator's ground (chapter 5) is open at the sides, and spheres roll on without
# rolling resistance until they fall off its edge: four walls make a pit 16 m wide around it.
walls = [box(f"wall_{side}", pos, half, type="static") for side, pos, half in (
    ("east", [8.5, 2, 0], [0.5, 2, 9]), ("west", [-8.5, 2, 0], [0.5, 2, 9]),
    ("north", [0, 2, 8.5], [8, 2, 0.5]), ("south", [0, 2, -8.5], [8, 2, 0.5]))]
write("settling-pile", "1,000 mixed bodies (spheres, hulls, boxes) dropped in a 10 x 10 x 10 block into a walled pit: they settle without overlapping or gaining energy.",
      walls, [{"metric": "penetration", "tolerance": 0.01,
            "why": "1 cm of overlap at rest, 1-2% of a body: where bodies still look like they touch"},
           {"metric": "energy_gain", "tolerance": 0.01,
            "why": "1% of the starting energy: contacts and friction only take energy; a gain is the solver's"},
           {"metric": "time_to_rest", "kinetic_fraction": 0.001, "tolerance": 5.0,
            "why": "5 s until the kinetic energy stays below 0.1% of the starting energy: real piles dropped from 2 m stop within a few bounces"}],
      8.0, "pile", generator={"stress": {"count": 1000, "density": "dense", "shape": "mixed"}})
