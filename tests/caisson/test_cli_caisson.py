"""``regimemap caisson``: the worked example in text and JSON, --example, bad files, the design sheet."""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import pytest

from regimemap.caisson.file import example_design_text, parse_design

from ..conftest import invoke_cli

EXAMPLE = example_design_text()

#: Goda's worked caisson, to three significant figures (docs/waves.md, Sect. 8).
WORKED = {"H13": 5.80, "Hmax": 8.05, "p1": 97.6, "p3": 87.2, "p4": 69.7, "pu": 65.7, "P": 941,
          "Mp": 4850, "U": 493, "Mu": 4930, "W": 2310, "SF_sliding": 1.16, "SF_overturning": 2.56,
          "L": 108, "eta_star": 11.9, "alpha1": 0.921, "alpha2": 0.318, "alpha3": 0.893,
          "alpha_I": 0.322, "gamma": 0.7, "kprime": -0.0180, "k": 0.278, "buoyancy": 0.318,
          "uplift_ratio": 0.524, "uplift_arm": 0.333}

REQUIRED_KEYS = {"H13", "Hmax", "L", "eta_star", "alpha1", "alpha2", "alpha3", "alpha_I", "p1", "p3",
                 "p4", "pu", "P", "Mp", "U", "Mu", "W", "SF_sliding", "SF_overturning", "gamma",
                 "kprime", "k", "buoyancy", "uplift_ratio", "uplift_arm", "mode"}


def sig3(x: float) -> str:
    return f"{x:.3g}"


@pytest.mark.slow
def test_example_prints_the_file_and_round_trips(tmp_path: Path) -> None:
    r = invoke_cli(["caisson", "--example"])
    assert r.code == 0 and r.stdout == EXAMPLE
    path = tmp_path / "mine.toml"
    path.write_text(r.stdout, encoding="utf-8")
    d = parse_design(path.read_text(encoding="utf-8"))
    assert d == parse_design(EXAMPLE)
    j = json.loads(invoke_cli(["caisson", str(path), "--json"]).stdout)
    assert sig3(j["P"]) == "941"


@pytest.mark.slow
def test_text_report(goda: Path) -> None:
    r = invoke_cli(["caisson", str(goda)])
    assert r.code == 0, r.output
    out = r.stdout
    for pattern in (r"H1/3\s+5\.796 m", r"Hmax\s+8\.050 m", r"eta\*\s+11\.87 m", r"p1\s+97\.64 kPa",
                    r"p3\s+87\.21 kPa", r"p4\s+69\.67 kPa", r"pu\s+65\.74 kPa", r"P\s+940\.6 kN/m",
                    r"Mp\s+4849 kN m/m", r"U\s+493\.0 kN/m", r"Mu\s+4930 kN m/m", r"W'\s+2312 kN/m",
                    r"sliding\s+1\.160", r"overturning\s+2\.559", r"gamma\s+0\.7000",
                    r"k\s+0\.277621", r"k'\s+-0\.0180155", r"buoyancy\s+0\.317613",
                    r"uplift ratio\s+0\.524144", r"uplift arm\s+0\.333333", r"gyration\s+0\.704746",
                    r"mode on the loaded map: RE \(rest\)",
                    r"k\s+up: \+12\.2% to k = 0\.311477 -> SL;\s+down: no change",
                    r"mu\s+down: -13\.8% to mu = 0\.517106 -> SL;\s+up: no change",
                    r"leaves rest at s = 1\.085\d \(Hmax = 8\.73\d m\): SL",
                    r"<=>\s+rest \(RE\) on the loaded map", r"both SF >= 1 and the mode is RE: consistent"):
        assert re.search(pattern, out), pattern
    assert r.stderr == ""


@pytest.mark.slow
def test_json_report(goda: Path) -> None:
    r = invoke_cli(["caisson", str(goda), "--json"])
    assert r.code == 0, r.output
    j = json.loads(r.stdout)
    assert REQUIRED_KEYS <= set(j)
    for key, value in WORKED.items():
        assert sig3(j[key]) == sig3(value), key
    assert j["mode"] == "RE" and j["consistent"] is True and j["at_rest_by_goda"] is True
    assert j["units"]["p1"] == "kPa" and j["units"]["P"] == "kN/m" and j["units"]["Mp"] == "kN*m/m"
    # 12 significant digits
    for key in REQUIRED_KEYS - {"mode"}:
        assert j[key] == float(f"{j[key]:.12g}")
    assert len(repr(j["k"]).lstrip("0.").rstrip("0")) <= 13
    assert j["margin"]["k"]["up"]["to"] == "SL" and sig3(j["margin"]["k"]["up"]["relative"]) == "0.122"
    assert j["margin"]["mu"]["down"]["to"] == "SL" and j["margin"]["mu"]["up"] is None
    path = j["path"]
    assert path["onset_mode"] == "SL" and 1.08 < path["onset_factor"] < 1.09
    assert [p["factor"] for p in path["points"]] == [round(0.5 + 0.1 * i, 12) for i in range(11)]
    assert {p["mode"] for p in path["points"]} == {"RE", "SL"}


BAD = [
    ("base_depth = 7.1", "base_depth = -7.1",
     r"line 23: \[caisson\] base_depth = -7\.1: out of range, below 0\.01 m.*; accepted: "),
    ("friction = 0.6", "friction = \"high\"",
     r"line 26: \[caisson\] friction = \"high\": expected a number.*accepted"),
    ("period = 11.4", "perod = 11.4", r"line 16: unknown key \[wave\] perod \(did you mean 'period'\?\)"),
    ("depth = 10.1", "depth = 6.0", r"line 23: \[caisson\] base_depth = 7\.1: .*deeper than the water"),
    ("[site]", "[site", r"TOML syntax error at line \d+"),
]


@pytest.mark.parametrize(("old", "new", "pattern"), BAD)
def test_bad_file_exits_2_with_one_line_and_writes_nothing(tmp_path: Path, old: str, new: str,
                                                           pattern: str) -> None:
    text = re.sub(rf"^{re.escape(old)}(?=[ \t]|$)", new, EXAMPLE, count=1, flags=re.MULTILINE)
    assert text != EXAMPLE
    design = tmp_path / "breakwater.toml"
    design.write_text(text, encoding="utf-8")
    before = sorted(os.listdir(tmp_path))
    r = invoke_cli(["caisson", str(design), "-o", str(tmp_path / "sheet.pdf")])
    assert r.code == 2, r.output
    assert r.stdout == "" and "Traceback" not in r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1
    assert str(design) in lines[0] and re.search(pattern, lines[0]), lines[0]
    assert sorted(os.listdir(tmp_path)) == before


def test_usage_errors(tmp_path: Path, goda: Path) -> None:
    goda.with_name("binary.toml").write_bytes(b"abc\x94\x95")
    for args, pattern in (
        (["caisson"], "missing DESIGN.toml"),
        (["caisson", str(tmp_path / "absent.toml")], "cannot read the design file"),
        (["caisson", str(goda.with_name("binary.toml"))],
         r"binary\.toml: cannot read the design file: not a UTF-8 text file: byte 0x94 at offset 3, line 1 "),
        (["caisson", "--example", str(goda)], "--example prints the example file"),
        (["caisson", str(goda), "-o", str(tmp_path / "sheet.txt")], r"\.png, \.svg or \.pdf for the design sheet"),
        (["caisson", str(goda), "-o", str(tmp_path / "no" / "sheet.pdf")], "does not exist"),
    ):
        r = invoke_cli(args)
        assert r.code == 2, (args, r.output)
        assert len(r.stderr.strip().splitlines()) == 1 and re.search(pattern, r.stderr), r.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["binary.toml", "goda.toml"]


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_sheet_is_written_atomically_and_byte_stable(tmp_path: Path, goda: Path,
                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    out = tmp_path / "sheet.svg"
    r = invoke_cli(["caisson", str(goda), "-o", str(out)])
    assert r.code == 0 and r.stdout.splitlines()[-1] == str(out)
    first = out.read_bytes()
    assert first.startswith(b"<?xml") and b"</svg>" in first[-100:]
    r = invoke_cli(["caisson", str(goda), "-o", str(out)])
    assert out.read_bytes() == first

    # a writer that fails half-way leaves the old file, byte for byte, and nothing else
    import regimemap.drawing.save as save

    def broken(fig, target, fmt, dpi=None):
        with open(target, "wb") as fh:
            fh.write(b"half a sheet")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(save, "print_figure", broken)
    r = invoke_cli(["caisson", str(goda), "-o", str(out)])
    assert r.code == 1 and "cannot write" in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert out.read_bytes() == first
    assert sorted(p.name for p in tmp_path.iterdir()) == ["goda.toml", "sheet.svg"]


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.parametrize("suffix", ["pdf", "png"])
@pytest.mark.deep
def test_sheet_formats(tmp_path: Path, goda: Path, suffix: str) -> None:
    out = tmp_path / f"sheet.{suffix}"
    r = invoke_cli(["caisson", str(goda), "--json", "-o", str(out)])
    assert r.code == 0, r.output
    assert json.loads(r.stdout)["sheet"] == str(out)  # the path inside the one JSON object
    head = out.read_bytes()[:8]
    assert head.startswith(b"%PDF" if suffix == "pdf" else b"\x89PNG")


@pytest.fixture(scope="module")
def drawn_sheets():
    """``drawn_sheets(text)``: the sheet of a design file's text, drawn once for this module's tests
    (read-only: the tests measure its texts)."""
    from regimemap.caisson.report import caisson_report
    from tests.conftest import draw_sheet

    sheets: dict[str, object] = {}

    def sheet(text: str):
        if text not in sheets:
            report = caisson_report(parse_design(text).analysis_inputs())
            fig = draw_sheet(report, title="breakwater.toml")
            fig.draw_without_rendering()  # laid out as drawn, without the pixels
            sheets[text] = (report, fig)
        return sheets[text]
    return sheet


@pytest.mark.render
@pytest.mark.deep
def test_sheet_has_its_panels(drawn_sheets) -> None:
    from regimemap.caisson.figures.page import PANELS, SHEET_SIZE

    report, fig = drawn_sheets(EXAMPLE)
    assert tuple(fig.get_size_inches()) == pytest.approx(SHEET_SIZE)
    axes = {ax.get_label(): ax for ax in fig.axes}
    assert tuple(axes) == PANELS
    texts = {name: " ".join(t.get_text() for t in ax.texts) + " " + ax.get_title(loc="left")
             for name, ax in axes.items()}
    assert "cross-section" in texts["section"] and "SWL" in texts["section"]
    assert "2B = 15.0 m" in texts["section"] and "h$_c$ = 3.40 m" in texts["section"]
    assert "p$_1$ = 97.64 kPa" in texts["pressure"] and "p$_3$ = 87.21 kPa" in texts["pressure"]
    assert "p$_4$ = 69.67 kPa" in texts["pressure"] and "\u03b7* = 11.87 m" in texts["pressure"]
    assert "p$_u$ = 65.74 kPa" in texts["uplift"]
    assert "loaded regime map" in texts["map"] and "design wave" in texts["map"]
    assert "leaves rest at 1.085" in texts["map"]
    assert "as the wave grows" in texts["path"]
    for number in ("97.64", "940.6", "1.160", "2.559", "0.2776", "RE", "+12.2% \u2192 SL"):
        assert number in texts["table"], number
    # the map: filled regions (the map's polygons, tests/caisson/test_figures_sheet.py) and the path (a
    # line through the design point at mu)
    ax = axes["map"]
    assert ax.patches
    path_lines = [ln for ln in ax.lines if len(ln.get_xdata()) == report.path.factors.size]
    assert path_lines and set(path_lines[0].get_ydata()) == {report.mu}
    assert ax.get_legend() is not None
    # every text of the sheet lies on the page (tick labels: those of ticks in view; drawn by the fixture)
    renderer = fig.canvas.get_renderer()
    w, h = fig.bbox.width, fig.bbox.height
    texts_drawn = list(fig.texts)
    for ax in fig.axes:
        texts_drawn += [*ax.texts, ax.title, ax._left_title, ax.xaxis.label, ax.yaxis.label]
        if ax.get_legend() is not None:
            texts_drawn += ax.get_legend().get_texts()
        for axis, lim in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
            lo, hi = min(lim), max(lim)
            texts_drawn += [t.label1 for t in axis.get_major_ticks()
                            if lo <= t.get_loc() <= hi and t.label1.get_visible()]
    assert len(texts_drawn) > 100
    for t in texts_drawn:
        if not t.get_text():
            continue
        bb = t.get_window_extent(renderer)
        assert bb.x0 >= -1 and bb.y0 >= -1 and bb.x1 <= w + 1 and bb.y1 <= h + 1, t.get_text()


DEEP = """
[site]
depth = 22.0
armour_depth = 14.0
seabed_slope = 0.02
[wave]
H13 = 7.5
Hmax = 12.5
period = 14.0
[caisson]
width = 24.0
base_depth = 16.0
crest = 6.0
berm_width = 12.0
friction = 0.6
concrete_fraction = 0.25
concrete_density = 2400
fill_density = 2000
fill_density_above = 1700
"""
LIGHT = EXAMPLE.replace("buoyant_weight = 2312", "buoyant_weight = 1300")


@pytest.mark.render
@pytest.mark.parametrize("text", [EXAMPLE, DEEP, LIGHT], ids=["goda", "deep-filled", "light"])
def test_sheet_texts_do_not_collide(drawn_sheets, text: str) -> None:
    """No two labels, titles or notes of the sheet overlap (tick labels aside), all on the page."""
    _, fig = drawn_sheets(text)
    renderer = fig.canvas.get_renderer()
    texts = [t for t in fig.texts]
    for ax in fig.axes:
        texts += [*ax.texts, ax.title, ax._left_title, ax.xaxis.label, ax.yaxis.label]
    boxes = [(t.get_text(), t.get_window_extent(renderer)) for t in texts if t.get_text().strip()]
    assert len(boxes) > 60
    hits = [(a, b) for i, (a, ba) in enumerate(boxes) for b, bb in boxes[i + 1:]
            if ba.overlaps(bb)]
    assert not hits, hits
    w, h = fig.bbox.width, fig.bbox.height
    for text_, bb in boxes:
        assert bb.x0 >= 0 and bb.y0 >= 0 and bb.x1 <= w and bb.y1 <= h, text_


@pytest.mark.slow
def test_random_command_lines_exit_cleanly(tmp_path: Path) -> None:
    """Any mix of the options: exit 0, 1 or 2, one error line, no traceback, no leftovers."""
    from hypothesis import given, settings
    from hypothesis import strategies as st

    good = tmp_path / "goda.toml"
    good.write_text(EXAMPLE, encoding="utf-8")
    bad = tmp_path / "bad.toml"
    bad.write_text(EXAMPLE.replace("width = 15.0", "width = 0"), encoding="utf-8")
    pieces = st.sampled_from([
        [str(good)], [str(bad)], [str(tmp_path / "absent.toml")], [str(tmp_path)], ["--example"],
        ["--json"], ["-o", str(tmp_path / "out" / "s.svg")], ["-o", str(tmp_path / "s.txt")],
        ["-o", ""], ["--bogus"], ["x", "y"]])

    @settings(max_examples=25, deadline=None, derandomize=True)
    @given(st.lists(pieces, max_size=3))
    def run(parts: list[list[str]]) -> None:
        argv = ["caisson", *[a for p in parts for a in p]]
        r = invoke_cli(argv)
        assert r.code in (0, 2), (argv, r.output)
        assert "Traceback" not in r.output and "internal error" not in r.stderr
        if r.code:
            assert len(r.error_lines()) == 1, (argv, r.stderr)
        assert not [p for p in tmp_path.rglob("*") if p.suffix in (".part", ".svg", ".txt")]

    run()
