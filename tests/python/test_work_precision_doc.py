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
