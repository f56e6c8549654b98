"""Sanity of the work-precision benchmark (scripts/bench_work_precision --quick).

One small grid point per code on the Hopland tow manoeuvre (660 s; the chain mooring on the
seabed behind the slow marker): our FMU with 10 elements
(relTol 1e-6) and MoorDyn with 10 segments at 0.9 x its stable step, both against our 40-element
reference. Only sanity is asserted here; speed targets live in the benchmark output, never in
timed tests.
"""

import math

import pytest

pytest.importorskip("moordyn")


def test_quick_benchmark_hopland(fmu_file):
    from studies.benchmarks import work_precision as wp

    case = wp.make_cases()["hopland"]
    ref, runs, limits = wp.run_case(fmu_file, case, quick=True)
    ours = [r for r in runs if r.code == "ours"]
    md = [r for r in runs if r.code == "MoorDyn"]
    assert len(ours) == 1 and len(md) == 1, "MoorDyn blew up even below its bisected stable step"

    for r in runs:
        assert all(math.isfinite(v) for v in r.errors.values()), r.label
        assert r.cpu > 0

    # MoorDyn's stable RK2 step is set by the axial wave crossing one segment: a Courant number
    # of order one (0.3 .. 3 x segment length / sqrt(EA/m)) shows the bisection found that limit.
    dt_lim, courant = limits[10]
    assert 0.3 < courant < 3.0, f"MoorDyn stable limit {dt_lim:g} s = {courant:.2f} x l/c"

    # Our 10 elements against our 40: the far end converges fast (cubic elements); 0.1 m is
    # 0.03 % of the 300 m cable and 3x what the full benchmark measured (0.029 m RMS).
    assert ours[0].errors["end_rms"] < 0.1
    # Tension: RMS within 1 % of the tension range over the run (measured 0.18 %).
    assert ours[0].errors["tension_rms"] < 0.01

    # Reference agreement between the codes: MoorDyn with 10 lumped-mass segments is second order
    # in the segment length; its end-position RMS error at N = 10 was measured independently
    # (0.30 m). 1 m (0.33 % of the cable length) separates that discretization error from a
    # modelling mismatch (drag convention d vs pi d, a missing current or added mass move the end
    # by metres), and the tension must agree within 5 % of its range.
    assert md[0].errors["end_rms"] < 1.0
    assert md[0].errors["tension_rms"] < 0.05
    # The force of the cable on the tow point has the same sign convention in both codes.
    assert (md[0].force[1:, 0] * ref.force[1:, 0] > 0).all()
    assert (md[0].force[1:, 2] * ref.force[1:, 2] > 0).all()


@pytest.mark.slow
def test_quick_benchmark_mooring_seabed(fmu_file):
    """Chain mooring on the seabed, quick size: our 10 elements and MoorDyn 10 segments
    against our 20-element reference, both with the matched seabed (seabedStiffness = kBot d)."""
    from studies.benchmarks import work_precision as wp

    case = wp.make_cases()["mooring"]
    ref, runs, limits = wp.run_case(fmu_file, case, quick=True)
    md = [r for r in runs if r.code == "MoorDyn"]
    assert len(md) == 1, "MoorDyn blew up even below its bisected stable step"

    # MoorDyn's RK2 step is capped by the seabed, not by the axial waves (l/c = 33 ms at N = 10):
    # a resting node is an overdamped oscillator, mass m = (117 + Can rho pi d^2/4) per metre,
    # k = kBot d, c = cBot d per metre; its fast rate lambda = c/(2m) + sqrt((c/(2m))^2 - k/m) and
    # RK2 is stable for lambda dt <= 2. The bisection (3 % steps) must land within 25 % of that.
    d, rho = case.line["diameter"], 1025.0
    m = case.line["massPerLength"] + rho * math.pi * d * d / 4
    k, c = wp.MD_KBOT * d, wp.MD_CBOT * d
    lam = c / (2 * m) + math.sqrt((c / (2 * m)) ** 2 - k / m)
    dt_lim, _ = limits[10]
    assert 0.75 * 2 / lam < dt_lim < 1.25 * 2 / lam, (dt_lim, 2 / lam)

    # MoorDyn's fairlead tension RMS error at N = 10 was measured independently: 5.6 %;
    # twice that separates discretization error from a modelling mismatch (seabed units, drag
    # convention, a missing weight term each move the snap peaks by far more).
    assert md[0].errors["tension_rmsrel"] < 0.112
    # Mid-line position: the lumped-mass error scale is l^2 kappa / 8 with l = 83.5 m and
    # kappa ~ w / H ~ 1000 N/m / 1 MN: 0.9 m; 2 m allows the factor of the snap phases.
    assert md[0].errors["mid_rms"] < 2.0
