"""A current with no static equilibrium at the start (docs/model.md, "A start in still water, where the flow has no
static equilibrium"), through the FMU: a taut 410 m chain anchored 400 m off and 50 m down (MoorDyn's wavekin_2
chain) in -5 m/s along x, towards its anchor, starts from its still-water equilibrium with a warning; the same
chain in still water starts with the same shape and no warning."""

from ucable.fmu import CableFMU

CHAIN = {"length": 410.0, "diameter": 0.252, "massPerLength": 390.0, "EA": 1.674e9, "enableBending": False,
         "enableCompression": False, "Cdn": 1.37, "Cdt": 0.64, "nElements": 20, "bottomEnd": 1,
         "anchor.x": -400.0, "anchor.y": 0.0, "anchor.z": -50.0, "enableSeabed": True, "waterDepth": 50.0}


def start(fmu_file, current: float):
    c = CableFMU(fmu_file, parameters=CHAIN, logging_on=True)
    c.initialize(inputs={"tow.x": 0.0, "tow.y": 0.0, "tow.z": 0.0, "current.x": current})
    shape = [c.get(f"shape.x[{k}]") for k in range(1, 22)] + [c.get(f"shape.z[{k}]") for k in range(1, 22)]
    warnings = [m for s, _, m in c.messages if s == "WARNING"]
    return c, shape, warnings


def test_a_current_without_equilibrium_starts_from_still_water_with_a_warning(fmu_file):
    c, shape, warnings = start(fmu_file, -5.0)
    calm, calm_shape, calm_warnings = start(fmu_file, 0.0)
    try:
        ours = [w for w in warnings if "no static equilibrium in the flow at t = 0 s: it would push the line into its anchor" in w]
        assert len(ours) == 1, warnings
        assert "compression of" in ours[0] and "still water" in ours[0] and "start transient" in ours[0]
        assert not any("still water" in w for w in calm_warnings)
        assert max(abs(a - b) for a, b in zip(shape, calm_shape)) < 1e-9
        # the current acts from t = 0: the chain moves off its still-water shape towards the anchor
        for cable in (c, calm):
            cable.do_step(1.0, 0.0)
        assert c.get("shape.x[11]") - calm.get("shape.x[11]") < -0.01
    finally:
        c.free()
        calm.free()
