"""``regimemap outcome -o map.json`` (the schema), ``--no-refine``, ``--quiet``, and the progress bars of
``outcome``, ``dynamics-figures`` and ``figures`` (shown on a terminal only)."""

from __future__ import annotations

import json

import numpy as np
import pytest

import regimemap.cli._progress as progress_module
from regimemap.dynamics import Block
from regimemap.dynamics.outcome import MapRuns, outcome_map, planned_refinement_runs, staged_outcome_map

from ..conftest import invoke_cli

MR = ["--gamma", "3", "--half-width", "0.2", "--kprime", "0", "--mu", "5", "--pulse", "half-sine"]
SWEEP = ["--k-peak", "0.3:1.5:9", "--duration", "0.25,0.5,1"]


def _on_a_terminal(monkeypatch: pytest.MonkeyPatch) -> None:
    """Standard error is a terminal, and a bar is drawn at once."""
    monkeypatch.setattr(progress_module, "_stderr_is_terminal", lambda: True)
    monkeypatch.setattr(progress_module, "DELAY", 0.0)


@pytest.fixture
def terminal(monkeypatch):
    """Standard error is a terminal, and a bar is drawn at once."""
    _on_a_terminal(monkeypatch)


@pytest.fixture(scope="module")
def mr_json(tmp_path_factory):
    """``regimemap outcome`` of the Makris-Roussos block over SWEEP, written as JSON, on a terminal:
    the run (exit code, stdout, stderr with its progress bars), the file and its contents --
    computed once for the schema and the progress-bar tests."""
    out = tmp_path_factory.mktemp("outcome") / "map.json"
    with pytest.MonkeyPatch.context() as mp:
        _on_a_terminal(mp)
        r = invoke_cli(["outcome", *MR, *SWEEP, "-o", str(out)])
    assert r.code == 0, r.output
    return r, out, json.loads(out.read_text())


@pytest.mark.slow
@pytest.mark.deep
def test_json_schema(mr_json):
    r, out, d = mr_json
    assert r.stdout.splitlines() == [str(out)]
    assert "boundaries refined" in r.stderr
    assert set(d) == {"first", "second", "axes", "labels", "category", "max_rotation", "residual_slide",
                      "refined", "boundaries", "min_rotation", "inputs"}
    assert (d["first"], d["second"]) == ("k_peak", "duration") and d["refined"] is True
    k, T = np.array(d["axes"]["k_peak"]), np.array(d["axes"]["duration"])
    np.testing.assert_allclose(k, np.linspace(0.3, 1.5, 9))
    assert T.tolist() == [0.25, 0.5, 1.0]
    assert len(d["category"]) == 3 and all(len(row) == 9 for row in d["category"])
    assert {c for row in d["category"] for c in row} <= set(d["labels"])
    assert d["category"][0][0] == "rest" and d["category"][2][-1] == "overturned"
    assert np.asarray(d["max_rotation"]).shape == (3, 9)
    assert d["inputs"]["pulse"] == "half-sine" and d["inputs"]["mu"] == 5.0
    pairs = set()
    for b in d["boundaries"]:
        assert set(b) == {"between", "points"}
        a, c = b["between"]
        assert a in d["labels"] and c in d["labels"] and a != c
        pairs.add((a, c))
        pts = np.asarray(b["points"], dtype=float)
        assert pts.ndim == 2 and pts.shape[1] == 2 and len(pts) >= 2
        # x the first swept input (k_peak), y the second (duration), in their units
        assert np.all((pts[:, 0] >= 0.3) & (pts[:, 0] <= 1.5) & (pts[:, 1] >= 0.25) & (pts[:, 1] <= 1.0))
    assert ("rock only", "overturned") in pairs and ("rest", "rock only") in pairs
    over = next(np.asarray(b["points"]) for b in d["boundaries"] if b["between"] == ["rock only", "overturned"])
    at_half = over[np.abs(over[:, 1] - 0.5) < 1e-12, 0]
    assert at_half.tolist() == pytest.approx([0.5747], rel=2e-3)  # the refined threshold, not a node


@pytest.mark.render
@pytest.mark.deep
def test_no_refine_and_quiet(tmp_path):
    out, png = tmp_path / "map.json", tmp_path / "map.png"
    r = invoke_cli(["outcome", *MR, *SWEEP, "--no-refine", "--quiet", "-o", str(out), "-o", str(png)])
    assert r.code == 0, r.output
    assert r.stderr == "" and r.stdout.splitlines() == [str(out), str(png)]
    d = json.loads(out.read_text())
    assert d["refined"] is False and d["boundaries"] == []
    assert png.read_bytes()[:4] == b"\x89PNG"


@pytest.mark.slow
@pytest.mark.deep
def test_outcome_progress_bars_on_a_terminal(tmp_path, terminal, mr_json):
    r = mr_json[0]  # the run of SWEEP on a terminal (the bars do not depend on the output format)
    assert "\rsimulating:" in r.stderr and "/27 [" in r.stderr and "\rrefining boundaries:" in r.stderr
    # --quiet: no bar, nothing on standard error, for any sweep (a small one that is refined too)
    out = tmp_path / "map.npz"
    r = invoke_cli(["outcome", *MR, "--k-peak", "0.3,1.5", "--duration", "0.25,1", "-q", "-o", str(out)])
    assert r.code == 0 and r.stderr == "" and out.is_file()


@pytest.mark.slow
@pytest.mark.deep
def test_library_progress_counts_every_run():
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    done: list[int] = []
    # 5 x 2 cells whose boundaries the refinement follows (rocking, overturning and rest meet)
    m = outcome_map(blk, "half-sine", ("k_peak", np.linspace(0.3, 1.5, 5)), ("duration", [0.25, 0.5]),
                    progress=done.append)
    assert m.crossings is not None and m.crossings.runs > 0 and sum(done) == 10 + m.crossings.runs
    runs = MapRuns(blk, "half-sine", "k_peak", "duration")
    stages: dict[str, list[int]] = {}
    totals: dict[str, int] = {}

    import contextlib

    @contextlib.contextmanager
    def bars(total, what):
        totals[what] = total
        stages[what] = []
        yield stages[what].append

    m2 = staged_outcome_map(runs, np.linspace(0.3, 1.5, 5), [0.25, 0.5], bars=bars)
    assert totals == {"simulating": 10, "refining boundaries": planned_refinement_runs(m2)}
    assert sum(stages["simulating"]) == 10
    assert 0 < sum(stages["refining boundaries"]) <= totals["refining boundaries"]
    assert np.array_equal(m2.category, m.category)
    assert np.array_equal(m2.crossings.fraction, m.crossings.fraction)


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_dynamics_figures_progress_and_quiet(tmp_path, terminal, monkeypatch):
    import dataclasses

    import regimemap.dynamics.presets as dp

    f = dp.DYNAMICS_FIGURES["D.3"]
    monkeypatch.setattr(dp, "DYNAMICS_FIGURES", {"D.3": dataclasses.replace(f, first=f.first[:3] + (6,),
                                                                          second=f.second[:3] + (5,))})
    r = invoke_cli(["dynamics-figures", "--out", str(tmp_path), "--format", "png"])
    assert r.code == 0, r.output
    assert "\rD.3 simulating:" in r.stderr and "D.3: " in r.stderr
    r = invoke_cli(["dynamics-figures", "--out", str(tmp_path), "--format", "png", "--quiet"])
    assert r.code == 0 and r.stderr == "" and r.stdout.splitlines() == [str(tmp_path / "dyn-D.3.png")]


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_figures_progress(tmp_path, terminal):
    r = invoke_cli(["figures", "--out", str(tmp_path), "--set", "worked", "--jobs", "1", "--dpi", "40"])
    assert r.code == 0, r.output
    assert "\rfigures:" in r.stderr and "/4 [" in r.stderr
    r = invoke_cli(["figures", "--out", str(tmp_path), "--set", "worked", "--jobs", "1", "--dpi", "40", "-q"])
    assert r.code == 0 and r.stderr == ""


@pytest.mark.subprocess
@pytest.mark.slow
def test_write_figures_reports_each_figure_from_the_workers(tmp_path):
    from regimemap.cli.plot import figure_maps
    from regimemap.maps.figures.batch import write_figures

    done: list[int] = []
    written = write_figures(tmp_path, ["W.1", "W.2", "W.3"], ["png"], 40, figure_maps, jobs=2,
                            progress=done.append)
    assert sum(done) == 3 and [p.name for p in written] == ["fig-W.1.png", "fig-W.2.png", "fig-W.3.png"]


@pytest.mark.slow
@pytest.mark.deep
def test_min_rotation_in_the_categories_title_key_and_json(tmp_path):
    out = tmp_path / "map.json"
    sweep = ["--k-peak", "0.3:1.5:5", "--duration", "0.25,0.5"]
    # --no-refine: the grid's categories are the same (the boundaries, not checked here, are refined)
    r = invoke_cli(["outcome", *MR, *sweep, "--min-rotation", "0.5", "--no-refine", "-o", str(out)])
    assert r.code == 0, r.output
    d = json.loads(out.read_text())
    assert d["min_rotation"] == pytest.approx(np.radians(0.5)) and d["inputs"]["min_rotation"] == 0.5
    blk = Block(B=0.2, gamma=3.0, mu=5.0)
    from regimemap.motion.figures.outcome import outcome_figure, outcome_title

    m = outcome_map(blk, "half-sine", ("k_peak", np.linspace(0.3, 1.5, 5)), ("duration", [0.25, 0.5]),
                    min_rotation=np.radians(0.5), refine=False)
    assert [[c for c in row] for row in d["category"]] == [[m.labels[c] for c in row] for row in m.category]
    fig, ax, art = outcome_figure(m, title=outcome_title("half-sine", {"mu": 5.0}, None, m.min_rotation), dpi=40)
    assert "rocking from 0.5°" in art.title.get_text()
    assert "rocking: max rotation > 0.5°" in [t.get_text() for t in art.legend.get_texts()]
