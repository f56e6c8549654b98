"""A partial run of scripts/bench_work_precision (--cases ...) updates only its own sections of the
generated report: an existing case section is replaced, a new one goes after the case it follows."""

from ucable import work_precision as wp


def test_partial_runs_splice_their_sections_into_the_report():
    cases = wp.make_cases()
    heave, waves = cases["heave"], cases["heave_waves"]
    doc = "\n".join(["# Performance", "", "## Targets at a glance", "glance", "",
                     f"## {heave.title}", "calm table", "### What each switch costs", "switches", "",
                     "## Where the unmet targets come from (measured; not relaxed)", "limits", ""])
    new = f"## {waves.title}\n\nwaves table v1\n"
    once = wp.splice_sections(doc, [(waves, None, [], new, None)])
    lines = once.split("\n")
    assert lines.index(f"## {waves.title}") > lines.index("switches")  # after the calm heave section
    assert lines.index(f"## {waves.title}") < lines.index("## Where the unmet targets come from (measured; not relaxed)")
    twice = wp.splice_sections(once, [(waves, None, [], f"## {waves.title}\n\nwaves table v2\n", None)])
    assert "waves table v1" not in twice and twice.count(f"## {waves.title}") == 1
    assert twice.replace("v2", "v1") == once  # nothing else moved
    assert "calm table" in twice and "glance" in twice and "limits" in twice


def test_partial_runs_update_their_rows_of_the_targets_at_a_glance(monkeypatch):
    cases = wp.make_cases()
    mooring = cases["mooring"]
    doc = "\n".join(["# Performance", "", "## Targets at a glance", "intro", "",
                     "| case | target | measured | verdict |", "|---|---|---|---|",
                     "| hopland | t1 | 50 | met |", "| mooring | t2 | 0.5 | NOT met |",
                     "| mooring | t3 | 0.6 | NOT met |", "| stiff | t4 | 11 | met |", "",
                     f"## {mooring.title}", "| mooring | not the glance table | | |", ""])
    monkeypatch.setattr(wp, "glance_table", lambda sections: "\n".join(
        ["## Targets at a glance", "", "| case | target | measured | verdict |", "|---|---|---|---|",
         "| mooring | t2 | 0.9 | NOT met |", "| mooring | t3 | 1.2 | met |"]))
    lines = wp.splice_glance(doc, [(mooring, None, [], "", None)]).split("\n")
    assert lines[7:11] == ["| hopland | t1 | 50 | met |", "| mooring | t2 | 0.9 | NOT met |",
                           "| mooring | t3 | 1.2 | met |", "| stiff | t4 | 11 | met |"]
    assert "| mooring | not the glance table | | |" in lines  # rows outside the glance table stay
