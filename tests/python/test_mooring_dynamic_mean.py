"""Mooring surge scene: our dynamic mean fairlead tension against MoorDyn's (studies.benchmarks.mooring_dynamics,
docs/mooring_dynamic_mean.md). The requirement is the dynamic mean within 0.5 % of the quasi-static
mean; test_mooring.py::test_surge_mean_tension_is_quasi_static records (xfail) that the 10 s surge
misses it. These tests establish with an independent code (MoorDyn 2.7.2) that the miss is the
physics of the scene (drag-driven slack and snap), not our discretization, and that the bound holds
once the surge is slow.

Excesses are in percentage points of the quasi-static mean, measured by scripts/mooring_dynamic_mean
(mean over the half-open window [100, 300) s). "Error estimate" of a code at a resolution N is its
own refinement behaviour: where it converges at first order (X = X_inf + C h), the error of the
finer run of a pair is the change |X(2N) - X(N)| and that of the coarser one twice it; where the
sequence does not contract, the largest change seen to any finer mesh that was run."""

import pytest

from studies.cases import mooring as m
from studies.benchmarks import mooring_dynamics as md

pytest.importorskip("moordyn")


@pytest.mark.slow
def test_snapping_surge_mean_excess_is_physics_in_both_codes(fmu_file):
    # T = 10 s, drag on (the reference scene): ours 40 elements (relTol 1e-8) and MoorDyn 40 segments
    # (its usual BA/-zeta -0.8 at 0.9 x its stable RK2 step). Measured excess:
    #   ours     20 / 40 / 80 / 160 elements:          2.132 / 2.441 / 2.650 / 2.608
    #   MoorDyn  20 / 40 / 80 / 160 / 320 segments:    2.728 / 2.899 / 2.951 / 3.005 / 3.076
    #   (ours relTol 1e-10 at 20 elements: 2.127; MoorDyn with our axial damping: 2.91 .. 3.15)
    # Neither sequence contracts geometrically, so the error estimate at 40 is the largest change
    # to any finer mesh: ours max(0.209, 0.167) = 0.209, MoorDyn max(0.052, 0.106, 0.177) = 0.177.
    # The required 0.5 % is unreachable for this scene if both codes put the mean above it by more
    # than their error estimate (measured margins: ours 2.441 - 0.209 = 2.23, MoorDyn 2.72 points).
    # With our default two-sided axial law the codes do NOT agree within these estimates (finest
    # runs 2.608 vs 3.076: 0.47 points, last refinement changes 0.04 and 0.07): our rod carries
    # compression in the slack phase (down to -422 kN), MoorDyn's segments cannot; with our
    # tension-only law they do agree (next test).
    qs = m.quasi_static_mean(40)
    ours = md.ours(fmu_file, 40, 1e-8, qs_mean=qs)
    theirs = md.moordyn(40, 0.9 * md.moordyn_dt(40), qs_mean=qs)
    assert theirs is not None, "MoorDyn blew up"
    assert ours.deviation - 0.00209 > 0.005
    assert theirs.deviation - 0.00177 > 0.005
    # and the line does go slack at the fairlead (the mechanism): below 10 % of the static tension
    assert ours.t_min < 0.1 * m.closed_form().fairlead_tension
    assert theirs.t_min < 0.1 * m.closed_form().fairlead_tension


@pytest.mark.slow
def test_snapping_surge_tension_only_agrees_with_moordyn(fmu_file):
    # The reference scene with our tension-only law (enableCompression = 0, MoorDyn's) against
    # MoorDyn 40 segments (BA/-zeta -0.8). Measured excess: ours tension-only 20 / 40 / 80
    # elements 3.029 / 2.992 / 3.116; MoorDyn as above (2.899 at 40 ... 3.076 at 320).
    # Neither sequence contracts, so each code's error estimate at 40 is its largest change to a
    # finer run: ours 0.124, MoorDyn 0.177; bound 0.301 points (measured gap 0.093; with the
    # two-sided law the gap is 0.458 at 40 / 40 and 0.47 at the finest runs).
    qs = m.quasi_static_mean(40)
    ours = md.ours(fmu_file, 40, 1e-8, qs_mean=qs, compression=False)
    theirs = md.moordyn(40, 0.9 * md.moordyn_dt(40), qs_mean=qs)
    assert theirs is not None, "MoorDyn blew up"
    assert abs(ours.deviation - theirs.deviation) < 3.01e-3
    # the law acts on each element's mean tension: measured minimum -31 kN at 40 elements, against
    # -324 kN with the two-sided law; bound 10 % of the static tension
    assert ours.min_axial > -0.1 * m.closed_form().fairlead_tension


@pytest.mark.slow
def test_surge_without_drag_agrees_with_moordyn(fmu_file):
    # T = 10 s, drag off: no slack (smallest fairlead tension ~0.5 MN) and a mean BELOW the
    # quasi-static one. Measured excess: ours 20 / 40 elements -2.665 / -2.650; MoorDyn 40 / 80
    # segments -2.762 / -2.711. Error estimates (first order): ours at 20 = twice its change to 40,
    # 0.030, MoorDyn at 80 = its change from 40, 0.051; bound 0.081 points (measured gap 0.046).
    qs = m.quasi_static_mean(40)
    ours = md.ours(fmu_file, 20, 1e-8, drag=False, qs_mean=qs)
    theirs = md.moordyn(80, 0.9 * md.moordyn_dt(80, drag=False), drag=False, qs_mean=qs)
    assert theirs is not None, "MoorDyn blew up"
    assert abs(ours.deviation - theirs.deviation) < 8.1e-4
    # the excess of the reference scene comes with the drag: without it the mean falls below
    assert ours.deviation < 0.0 and theirs.deviation < 0.0


@pytest.mark.slow
def test_slow_surge_mean_is_quasi_static_in_both_codes(fmu_file):
    # T = 100 s, drag on, same 5 m amplitude: no slack (minimum tension 1.35 MN), and the dynamic
    # mean approaches the quasi-static one. Measured excess: ours 20 / 40 elements -0.023 / -0.022,
    # MoorDyn 40 / 80 segments -0.035 / -0.023.
    qs = m.quasi_static_mean(40)
    ours = md.ours(fmu_file, 20, 1e-8, period=100.0, qs_mean=qs)
    # the 0.5 % criterion holds once the motion is slow
    assert abs(ours.deviation) < 5e-3
    assert ours.t_min > 1e6  # no slack in this variant
    theirs = md.moordyn(80, 0.9 * md.moordyn_dt(80, period=100.0), period=100.0, qs_mean=qs)
    assert theirs is not None, "MoorDyn blew up"
    # Error estimates (first order): ours at 20 = twice its change to 40 elements, 0.002 points;
    # MoorDyn at 80 = its change from 40 segments, 0.012 points (its lumped touchdown moves node
    # by node); bound 0.014 points = 1.4e-4 (measured gap < 0.001 points).
    assert abs(ours.deviation - theirs.deviation) < 1.4e-4
