"""A line type whose EA is a tension-strain file (MoorDyn's format, docs/lines.md) through the FMU: the file
next to the deck is read with it, and the line is the same, bit for bit, as the line given by the
parameters axialCurvePoints and axialCurve.strain/tension[k] (docs/model.md, "Non-linear axial stiffness").
"""

from __future__ import annotations

import math

# A taut polyester line, 800 m from an anchor at 200 m depth to a fairlead 10 m deep: 12 points of the
# stiffening law T = 1.5e8 eps + 1.5e9 eps^2 N up to 6 % strain.
STRAIN = [0.005 * (k + 1) for k in range(12)]
TENSION = [1.5e8 * e + 1.5e9 * e * e for e in STRAIN]
DECK = """MoorDyn v2 Input File
taut polyester line, EA from a tension-strain file
---------------------- LINE TYPES --------------------------------
TypeName   Diam    Mass/m  EA             BA/-zeta  EI   Cd    Ca    CdAx  CaAx
(name)     (m)     (kg/m)  (N)            (N-s/-)   (-)  (-)   (-)   (-)   (-)
poly       0.15    20.0    poly_curve.txt -0.8      0    1.2   1.0   0.2   0.0
---------------------- POINTS --------------------------------
ID   Attachment  X       Y     Z      Mass   Volume  CdA    CA
(#)   (-)        (m)     (m)   (m)    (kg)   (m^3)   (m^2)  (-)
1     Fixed      -800    0     -200   0      0       0      0
2     Coupled    0       0     -10    0      0       0      0
---------------------- LINES --------------------------------------
ID    LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)      (m)       (-)      (-)
1     poly       1        2        800       40       -
---------------------- OPTIONS -----------------------------------
200      WtrDpth
--------------------- need this line -------------------------------
"""
SECANT = TENSION[-1] / STRAIN[-1]  # MoorDyn's EA of a curve, also in its -zeta conversion
BY_PARAMETERS = {
    "length": 800.0, "diameter": 0.15, "massPerLength": 20.0, "EA": SECANT, "EI": 0.0,
    "axialDamping": 0.8 * (800.0 / 40) * math.sqrt(SECANT * 20.0),
    "Cdn": 1.2, "Cdt": 0.2, "Can": 1.0, "Cat": 0.0, "nElements": 20, "bottomEnd": 1,
    "anchor.x": -800.0, "anchor.y": 0.0, "anchor.z": -200.0,
    "waterDepth": 200.0, "gravity": 9.80665, "waterDensity": 1025.0,
    "enableSeabed": True, "seabedStiffness": 3.0e6 * 0.15, "seabedDamping": 3.0e5 * 0.15,
    "enableCompression": False,
    "axialCurvePoints": 12,
    **{f"axialCurve.strain[{k + 1}]": e for k, e in enumerate(STRAIN)},
    **{f"axialCurve.tension[{k + 1}]": t for k, t in enumerate(TENSION)},
}
OUTPUTS = ["towTension", "endTension", "towForce.x", "towForce.z"] + [f"tension[{k}]" for k in range(1, 22)]


def _run(cable, steps: int = 4, h: float = 0.5, speed: float = 0.5):
    """Statics at the fairlead, then a surge away from the anchor (the line stretches further)."""
    cable.initialize(inputs={"tow.z": -10.0, "tow.vx": speed})
    history = [cable.get_reals(OUTPUTS)]
    for k in range(steps):
        cable.set({"tow.x": speed * (k + 1) * h})
        cable.do_step(h)
        history.append(cable.get_reals(OUTPUTS))
    return history


def test_a_tension_strain_file_is_the_curve_of_the_parameters_bit_for_bit(make_cable, tmp_path):
    (tmp_path / "poly_curve.txt").write_text(
        "polyester working curve\nstrain tension\n(-) (N)\n" +
        "".join(f"{e!r} {t!r}\n" for e, t in zip(STRAIN, TENSION)) + "---\n")
    deck = tmp_path / "taut_poly.dat"
    deck.write_text(DECK)
    a = _run(make_cable(parameters={"lineFile": str(deck)}))
    b = _run(make_cable(parameters=BY_PARAMETERS))
    # the taut line's tension is the law's at its chord strain, not that of a constant EA
    chord = math.hypot(800.0, 190.0) / 800.0 - 1.0
    law = 1.5e8 * chord + 1.5e9 * chord * chord
    assert abs(a[0][0] / law - 1.0) < 1e-3, (a[0][0], law)
    assert abs(SECANT * chord / law - 1.0) > 0.2
    for k, (x, y) in enumerate(zip(a, b)):
        assert x.tobytes() == y.tobytes(), f"step {k}: {x - y}"
