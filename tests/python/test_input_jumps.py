"""A driven position input far from the trajectory the previous inputs extrapolated warns for every driven
input, as for the tow point (docs/interface.md, "How the FMU reads a driven end"): the far end of bottomEnd 3
(`end.*`, a driven far end or a third party's body), a mooring system's coupled bodies (`body[k].*`) and
coupled points (`point[k].*`). Each group is named in one warning per run, with the jump in metres and the
advice of a shorter step; a step that resolves the motion gets none.

The motion: a surge of 2 m with a 12 s period. At 10 s steps the inputs at the second communication point
are metres from where the extrapolation of the first ones put the end; at 0.5 s steps millimetres (the
extrapolation's error, jerk h^3 / 6, under the 0.05 m tolerance)."""

import math
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
W = 2.0 * math.pi / 12.0
AMPLITUDE = 2.0


def warnings_of(c):
    return [m for s, _, m in c.messages if s == "WARNING"]


def surge(c, group, h, steps):
    """Steps c with the x input of `group` ("end", "body[1]", "point[2]") surging about where it starts."""
    x = "end.x" if group == "end" else f"{group}.x"
    vx = "end.vx" if group == "end" else f"{group}.vx"
    x0 = c.get(x)
    for k in range(steps):
        t = k * h
        c.set({x: x0 + AMPLITUDE * math.sin(W * t), vx: AMPLITUDE * W * math.cos(W * t)})
        c.do_step(h, t=t)
    return warnings_of(c)


def jump_of(messages, group, what):
    """The warnings that name `group`'s position inputs, and the jump in metres of the first."""
    named = [m for m in messages if f"the {group} position input {group}.x/y/z" in m]
    m = re.search(rf"is (\S+) m from where the {re.escape(what)} stands", named[0]) if named else None
    return named, float(m.group(1)) if m else None


def driven_end(make_cable):
    """The default 300 m cable between a tow point at rest and a far end driven 290 m below it (bottomEnd 3)."""
    c = make_cable(parameters={"bottomEnd": 3})
    c.initialize(inputs={"end.x": 0.0, "end.y": 0.0, "end.z": -290.0, "end.vx": AMPLITUDE * W})
    return c


def test_a_driven_far_end_that_jumps_warns_once_naming_end_with_the_jump(make_cable):
    long = surge(driven_end(make_cable), "end", 10.0, 4)
    named, jump = jump_of(long, "end", "far end")
    assert len(named) == 1, long
    assert jump is not None and jump > 0.5, named[0]
    assert "shorter communication step" in named[0], named[0]
    assert not [m for m in long if "tow position input" in m], long  # the tow point stood still
    assert surge(driven_end(make_cable), "end", 0.5, 48) == []


def system(make_cable, deck, inputs=None):
    from studies.comparisons import mooring_system as ms

    c = make_cable(parameters=ms.fmu_parameters(ms.read_system_deck(deck)))
    c.initialize(inputs=inputs or {})
    return c


def deck_with_points(tmp_path):
    """The OC4 chains with a BODIES section: their Vessel points 4, 5, 6 are coupled points (point[k].*, absolute
    positions), placed where the deck puts them."""
    from studies.comparisons import mooring_system as ms

    text = ms.oc4_with_a_coupled_body()
    path = tmp_path / "points.dat"
    path.write_text(text)
    fairleads = ms.read_system_deck(ms.OC4).fairleads
    return path, {f"point[{k}].{c}": float(v) for k, r in zip((4, 5, 6), fairleads) for c, v in zip("xyz", r)}


def test_a_coupled_body_that_jumps_warns_once_naming_it_with_the_jump(make_cable):
    """The OC4 platform's three chains, the platform (body[1]) surging."""
    from studies.comparisons import mooring_system as ms

    long = surge(system(make_cable, ms.OC4), "body[1]", 10.0, 4)
    named, jump = jump_of(long, "body[1]", "reference point of body[1]")
    assert len(named) == 1, long
    assert jump is not None and jump > 0.5, named[0]
    assert "shorter communication step" in named[0], named[0]
    assert surge(system(make_cable, ms.OC4), "body[1]", 0.5, 48) == []


@pytest.mark.parametrize("point", [4, 6])
def test_a_coupled_point_that_jumps_warns_once_naming_it_with_the_jump(make_cable, tmp_path, point):
    """The OC4 chains from three coupled points, one of them surging; the others stand still and get no
    warning."""
    deck, start = deck_with_points(tmp_path)
    group = f"point[{point}]"
    long = surge(system(make_cable, deck, start), group, 10.0, 4)
    named, jump = jump_of(long, group, f"coupled point {group}")
    assert len(named) == 1, long
    assert jump is not None and jump > 0.5, named[0]
    assert "shorter communication step" in named[0], named[0]
    assert not [m for m in long if "position input" in m and group not in m], long
    assert surge(system(make_cable, deck, start), group, 0.5, 48) == []
