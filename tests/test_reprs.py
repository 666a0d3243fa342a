"""Notebook display of the main results: a readable ``repr`` and a small HTML table.

A classification (:class:`~regimemap.PointResult`), a map
(:class:`~regimemap.maps.MapData`), a caisson analysis
(:class:`~regimemap.waves.CaissonAnalysis`, :class:`~regimemap.caisson.report.CaissonReport`)
and a lifetime (:class:`~regimemap.lifetime.LifetimeResult`): the repr is one or
two lines without numpy's noise, the HTML parses as one table whose cells hold
the key numbers, and every text in it is escaped.
"""

from __future__ import annotations

from html.parser import HTMLParser

import numpy as np
import pytest

from regimemap import Parameters, query_point
from regimemap.caisson.report import caisson_report
from regimemap.lifetime import LifetimeResult
from regimemap.maps import compute_map
from regimemap.records.htmltable import cell_text, html_table
from regimemap.records.numbers import number, number_range
from regimemap.waves import analyse_caisson

GODA = dict(H0=6.3, period=11.4, seabed_slope=0.01, depth=10.1, armour_depth=5.6, base_depth=7.1,
            crest=3.4, berm_width=8.0, angle_deg=15.0, width=15.0, friction=0.6,
            buoyant_weight=2312e3)


class Table(HTMLParser):
    """The tags (with a balance check), the caption and the rows of cells of one table."""

    def __init__(self, text: str) -> None:
        super().__init__(convert_charrefs=True)
        self.tags: list[str] = []
        self.open: list[str] = []
        self.rows: list[list[str]] = []
        self.caption = ""
        self._cell: list[str] | None = None
        self._in_caption = False
        self.feed(text)
        self.close()

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.tags.append(tag)
        self.open.append(tag)
        if tag == "tr":
            self.rows.append([])
        elif tag in ("td", "th"):
            self._cell = []
        elif tag == "caption":
            self._in_caption = True

    def handle_endtag(self, tag: str) -> None:
        assert self.open and self.open[-1] == tag, f"</{tag}> closes <{self.open[-1:]}>"
        self.open.pop()
        if tag in ("td", "th") and self._cell is not None:
            self.rows[-1].append("".join(self._cell))
            self._cell = None
        elif tag == "caption":
            self._in_caption = False

    def handle_data(self, data: str) -> None:
        if self._cell is not None:
            self._cell.append(data)
        elif self._in_caption:
            self.caption += data

    def row(self, name: str) -> list[str]:
        for r in self.rows:
            if r and r[0] == name:
                return r[1:]
        raise KeyError(name)


def parse(text: str) -> Table:
    t = Table(text)
    assert not t.open, f"unclosed tags {t.open}"
    assert t.tags[0] == "table" and t.tags.count("table") == 1
    assert set(t.tags) <= {"table", "caption", "thead", "tbody", "tr", "th", "td"}
    return t


def assert_readable(text: str, lines: int = 2) -> None:
    assert 1 <= len(text.splitlines()) <= lines, text
    for noise in ("array(", "np.float64", "dtype", "<Mode.", "Hypothesis.", "Crossing("):
        assert noise not in text, text


# -- the helper ------------------------------------------------------------------------------------


def test_html_table_escapes_every_text() -> None:
    t = parse(html_table([("<b>x</b>", "a & b", None, True, np.float64(0.123456), np.int64(7),
                           np.array(2.5))], caption="<script>", header=("<i>", "v")))
    assert t.caption == "<script>"
    assert t.rows[0] == ["<i>", "v"]
    assert t.rows[1] == ["<b>x</b>", "a & b", "\u2013", "yes", "0.1235", "7", "2.5"]
    assert "<script>" not in html_table([("x", 1)], caption="<script>")


@pytest.mark.parametrize(("x", "text"), [(0.25252, "0.2525"), (-0.0, "0"), (1e-20, "1e-20"),
                                         (float("nan"), "n/a"), (float("inf"), "n/a"),
                                         (123456.0, "1.235e+05")])
def test_number(x: float, text: str) -> None:
    assert number(x) == text


def test_number_range_and_cells() -> None:
    assert number_range([1.0, 1.00001]) == "1"
    assert number_range([0.5, float("nan"), 2.0]) == "0.5 \u2026 2"
    assert number_range([float("nan")]) == "n/a"
    assert cell_text(np.bool_(False)) == "no"


# -- a classification ------------------------------------------------------------------------------


def test_point_result() -> None:
    r = query_point(0.5, 0.8, 3.0, 0.4)
    text = repr(r)
    assert_readable(text)
    assert text.startswith("PointResult(k=0.5, mu=0.8 (gamma=3, k'=0.4) -> RO (rock about O)")
    assert "margin k -52.4% -> RE, mu -70.8% -> SRO-" in text
    t = parse(r._repr_html_())
    assert t.caption == "k = 0.5, mu = 0.8 (gamma=3, k'=0.4)"
    assert t.row("mode") == ["RO", "rock about O"]
    assert t.row("fx")[0] == "0.2525" and t.row("fy")[0] == "1.083"
    assert t.row("thdd")[0] == "0.0825" and t.row("slip")[0] == "\u2013"
    assert t.row("margin k")[0] == "-52.4% -> RE"
    assert t.row("margin mu")[0] == "-70.8% -> SRO-"
    assert t.row("case")[0] == "1b"


def test_point_result_with_loads_a_name_and_section_4_7() -> None:
    r = query_point(4.0, 3.0, 0.7, -0.018, name="<caisson & co>", buoyancy=0.318,
                    uplift_ratio=0.524)
    assert_readable(repr(r))
    assert "beta = 0.318, nu = 0.524" in repr(r) and "least constraint" in repr(r)
    html = r._repr_html_()
    assert "<caisson" not in html
    t = parse(html)
    assert t.caption.startswith("<caisson & co>: k = 4, mu = 3")
    assert t.row("mode")[0] == "LO" and t.row("chosen by")[0] == "least constraint"
    assert t.row("loads")[0] == "beta = 0.318, nu = 0.524, e_u = 1/3"
    assert t.row("margin mu")[0] == "no change"
    r = query_point(3.5, 2.3, 3.0, -0.6)
    assert "Section 4.7" in repr(r) and parse(r._repr_html_()).row("chosen by")[0] == "Section 4.7"
    r = query_point(0.0, 0.8, 3.0, 0.4)
    assert "margin k +0.2381 -> RO" in repr(r)  # from 0, the absolute change


# -- a map -----------------------------------------------------------------------------------------


def test_map_data() -> None:
    d = compute_map(Parameters(3.0, 0.4), k_max=1.0, mu_max=1.2)
    text = repr(d)
    assert_readable(text)
    assert text.startswith("MapData(gamma=3, k'=0.4: final map, view k <= 1, mu <= 1.2;")
    assert "modes in view RE, SL, RO, SRO-" in text and "points O, A, C, D" in text
    t = parse(d._repr_html_())
    assert t.rows[0] == ["mode", "share of the view", "polygons", ""]
    assert t.row("RO")[0] == "61.5 %" and t.row("RE")[0] == "21.4 %"
    shares = [float(t.row(m.label)[0].rstrip(" %")) for m in d.modes]
    assert sum(shares) == pytest.approx(100.0, abs=0.3)  # the final map covers the view once
    assert "A (0.2381, 0.2381)" in t.row("points")[2]


def test_loaded_map_data() -> None:
    d = compute_map(Parameters(0.7, -0.018, buoyancy=0.318, uplift_ratio=0.524))
    assert_readable(repr(d))
    assert "beta = 0.318" in repr(d) and "LO" in repr(d)
    t = parse(d._repr_html_())
    assert float(t.row("LO")[0].rstrip(" %")) > 0.0


# -- a caisson -------------------------------------------------------------------------------------


def test_caisson_analysis() -> None:
    a = analyse_caisson(**GODA)
    text = repr(a)
    assert_readable(text)
    assert "Hmax=8.05 m" in text and "SF sliding 1.16" in text and "P=940.6 kN/m" in text
    t = parse(a._repr_html_())
    assert t.row("SF sliding")[0] == "1.16" and t.row("U")[0] == "493"
    assert t.row("gamma")[0] == "0.7" and t.row("k")[0] == "0.2776"


def test_caisson_analysis_of_many_conditions() -> None:
    a = analyse_caisson(**{**GODA, "width": np.linspace(10.0, 25.0, 16)})
    text = repr(a)
    assert_readable(text)
    assert text.startswith("CaissonAnalysis(16 conditions: ")
    assert "SF sliding 0.9506 \u2026 1.265" in text
    t = parse(a._repr_html_())
    assert t.caption == "Caisson analysis (Goda), 16 conditions"
    assert t.row("Hmax")[0] == "8.05"  # the same wave for every width


@pytest.mark.slow
def test_caisson_report() -> None:
    r = caisson_report(GODA)
    text = repr(r)
    assert_readable(text)
    assert text.startswith("CaissonReport(RE (rest) at k=0.2776, mu=0.6")
    assert "margin k +12.2% -> SL" in text and "consistent with the map" in text
    t = parse(r._repr_html_())
    assert t.row("mode")[0] == "RE" and t.row("SF sliding")[0] == "1.16"
    assert t.row("consistent")[0] == "yes"
    assert t.row("wave path")[0].startswith("leaves rest at 1.09 x the design wave")


# -- a lifetime ------------------------------------------------------------------------------------


def test_lifetime_result() -> None:
    r = LifetimeResult(sliding=np.array([0.0, 0.1, 0.3, 0.0, 1.2]),
                       max_storm=np.array([0.0, 0.05, 0.2, 0.0, 0.9]),
                       storms=np.array([3, 4, 2, 5, 6]), seed=1, years=50,
                       thresholds=(0.1, 0.3), width=15.0)
    assert_readable(repr(r), lines=1)
    t = parse(r._repr_html_())
    assert t.caption == "Lifetime sliding: ESD = 0.32 m over 50 years"
    assert t.row("expected sliding (ESD)") == ["0.32 m", "\u00b1 0.23 m (standard error)"]
    assert t.row("P(S > 0.1 m)") == ["40 %", "one storm alone: 40 %"]
    assert t.row("never slides")[0] == "40 %" and t.row("trials")[0] == "5"
