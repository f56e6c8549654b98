"""A partial run of scripts/bench_work_precision (--cases ...) updates only its own sections of the
generated report: an existing case section is replaced, a new one goes after the case it follows."""

from studies.benchmarks import work_precision as wp


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


def test_partial_runs_refresh_the_appendices(tmp_path):
    """The hand-written limits and the callgrind profile appended to the report are rewritten from
    their files by a partial run too (before, only a full run did), once, after the case sections."""
    mooring = wp.make_cases()["mooring"]
    (tmp_path / "performance_limits.md").write_text("## Where the unmet targets come from\n\nlimits v2\n")
    (tmp_path / "performance_profile.md").write_text("<!-- profile tables begin -->\n## Profile\n\nprofile v2\n")
    doc = "\n".join(["# Performance", "", "## Targets at a glance", "glance", "", f"## {mooring.title}",
                     "mooring v1", "### What each switch costs", "switches", "",
                     "## Where the unmet targets come from", "", "limits v1", "<!-- profile tables begin -->",
                     "## Profile", "", "profile v1", ""])
    text = wp.with_appendices(wp.splice_sections(doc, [(mooring, None, [], f"## {mooring.title}\n\nmooring v2\n", None)]),
                              tmp_path)
    assert "mooring v2" in text and "v1" not in text
    assert text.count("## Where the unmet targets come from") == 1 and text.count("## Profile") == 1
    assert text.index("mooring v2") < text.index("limits v2") < text.index("profile v2")
