"""regimemap.maps.figures.key: the map key (swatch, symbol column, plain descriptions)."""

from __future__ import annotations

import numpy as np
import pytest

from regimemap import MAP_MODES, Mode, Parameters
from regimemap.maps.figures.figure import map_figure
from regimemap.maps.figures.mapplot import MODE_STYLE
from regimemap.maps.run import run_map

pytestmark = pytest.mark.render


def _key_parts(legend):
    """For each entry: (handle box children, label Text)."""
    from matplotlib.offsetbox import DrawingArea

    rows = []
    for column in legend._legend_handle_box.get_children():
        for entry in column.get_children():
            box, text_area = entry.get_children()
            assert isinstance(box, DrawingArea)
            rows.append((box.get_children(), text_area.get_children()[0]))
    return rows


def _extent(artist, renderer):
    return artist.get_window_extent(renderer)


def test_map_key_entries_swatch_symbol_description():
    from matplotlib.colors import to_rgba
    from matplotlib.lines import Line2D
    from matplotlib.text import Text

    from regimemap.maps.figures.key import ModeSwatch

    fig, ax, art = map_figure(run_map(Parameters(3.0, 0.4)))
    labels = [t.get_text() for t in art.legend.get_texts()]
    shown = [m for m in MAP_MODES if m in art.fills and art.fills[m]]
    assert labels == [m.description for m in shown] + ["boundary of a region",
                                                        "construction line"]
    assert not any("$" in t for t in labels)  # descriptions are plain text
    for children, label in _key_parts(art.legend):
        swatches = [c for c in children if isinstance(c, ModeSwatch)]
        if not swatches:
            assert [type(c) for c in children] == [Line2D]
            continue
        (swatch,) = swatches
        st = MODE_STYLE[swatch.mode]
        assert label.get_text() == swatch.mode.description
        assert swatch.get_facecolor() == pytest.approx(to_rgba(st.color))
        assert swatch.get_hatch() == st.hatch
        (symbol,) = [c for c in children if isinstance(c, Text)]
        want = swatch.mode.tex[1:-1] if swatch.mode.tex[1:-1].isalpha() else swatch.mode.tex
        assert symbol.get_text() == want


def test_every_symbol_sits_between_its_swatch_and_the_descriptions():
    """All six modes, each font size used: swatch | symbol | description, never overlapping,
    and every description of a column starts at the same x."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure
    from matplotlib.text import Text

    from regimemap.drawing.style import style_context
    from regimemap.maps.figures.key import ModeSwatch, key_handles, key_legend

    for fontsize in (7.0, 8.5, 11.0):
        with style_context():
            fig = Figure(figsize=(7, 3), dpi=150)
            FigureCanvasAgg(fig)
            ax = fig.add_subplot()
            leg = key_legend(ax, key_handles(MAP_MODES, dotted_label=r"dotted $\mu = k|k'|$"),
                             ncols=2, fontsize=fontsize, loc="upper center")
            fig.draw_without_rendering()
            r = fig.canvas.get_renderer()
            starts: dict[float, set[float]] = {}
            rows = _key_parts(leg)
            assert len(rows) == len(MAP_MODES) + 3
            for children, label in rows:
                lab = _extent(label, r)
                swatch = next((c for c in children if isinstance(c, ModeSwatch)), None)
                first = children[0]
                col = round(_extent(first, r).x0, 1) if swatch is None else round(
                    _extent(swatch, r).x0, 1)
                starts.setdefault(col, set()).add(round(lab.x0, 1))
                if swatch is None:  # a line sample: as long as a swatch
                    continue
                sym = _extent(next(c for c in children if isinstance(c, Text)), r)
                sw = _extent(swatch, r)
                assert sw.x1 < sym.x0, (swatch.mode, fontsize)
                assert sym.x1 < lab.x0 - 0.15 * fontsize, (swatch.mode, fontsize)
                # the symbol stands on the label's baseline: same vertical band
                assert abs((sym.y0 + sym.y1) / 2 - (lab.y0 + lab.y1) / 2) < 0.5 * fontsize * 150 / 72
            assert len(starts) == 2 and all(len(v) == 1 for v in starts.values()), starts


def test_line_samples_are_as_long_as_the_swatches():
    from matplotlib.lines import Line2D

    from regimemap.maps.figures.key import ModeSwatch

    fig, ax, art = map_figure(run_map(Parameters(3.0, -0.3)))
    fig.draw_without_rendering()
    r = fig.canvas.get_renderer()
    widths = {}
    for children, _label in _key_parts(art.legend):
        for c in children:
            if isinstance(c, (ModeSwatch, Line2D)):
                widths.setdefault(type(c).__name__, set()).add(round(_extent(c, r).width, 0))
    assert set(widths) == {"ModeSwatch", "Line2D"}
    (w_swatch,) = widths["ModeSwatch"]
    assert all(abs(w - w_swatch) <= 2 for w in widths["Line2D"]), widths


def test_swatch_colour_in_the_raster():
    """The PNG shows each swatch in its mode's colour (between the hatch lines)."""
    from regimemap.maps.figures.key import ModeSwatch

    fig, ax, art = map_figure(run_map(Parameters(3.0, -0.3)), dpi=100)
    fig.canvas.draw()
    img = np.asarray(fig.canvas.buffer_rgba())[..., :3].astype(int)
    h = img.shape[0]
    r = fig.canvas.get_renderer()
    seen = 0
    for children, _ in _key_parts(art.legend):
        for c in children:
            if not isinstance(c, ModeSwatch):
                continue
            bb = _extent(c, r)
            patch = img[h - int(bb.y1) + 2:h - int(bb.y0) - 2, int(bb.x0) + 2:int(bb.x1) - 2]
            colours, counts = np.unique(patch.reshape(-1, 3), axis=0, return_counts=True)
            want = np.round(np.array(c.get_facecolor()[:3]) * 255).astype(int)
            top = colours[np.argmax(counts)]
            assert np.abs(top - want).max() <= 2, (c.mode, top, want)
            seen += 1
    assert seen == sum(1 for m in MAP_MODES if art.fills.get(m))


def test_ambiguity_overlay_keeps_the_key():
    """draw_ambiguity rebuilds the legend with one more entry; swatches and symbols stay."""
    from matplotlib.text import Text

    from regimemap.maps.ambiguity import ambiguous_in_view
    from regimemap.maps.figures.ambiguity import LEGEND_LABEL, draw_ambiguity
    from regimemap.maps.figures.key import ModeSwatch

    fig, ax, art = map_figure(run_map(Parameters(3.0, -0.6), k_max=4.0, mu_max=3.0))
    before = [(type(c[0]), [x.get_text() for x in c if isinstance(x, Text)])
              for c, _ in _key_parts(art.legend)]
    assert draw_ambiguity(ax, ambiguous_in_view(Parameters(3.0, -0.6), 4.0, 3.0), 4.0, 3.0)
    rows = _key_parts(ax.get_legend())
    after = [(type(c[0]), [x.get_text() for x in c if isinstance(x, Text)]) for c, _ in rows]
    assert after[:-1] == before and rows[-1][1].get_text() == LEGEND_LABEL
    assert sum(t is ModeSwatch for t, _ in after) == sum(1 for m in MAP_MODES if art.fills.get(m))


def test_atlas_key_has_every_mode():
    from regimemap.maps.figures.atlas import atlas_figure
    from regimemap.maps.figures.key import ModeSwatch
    from regimemap.maps.run_atlas import run_atlas

    fig = atlas_figure(run_atlas([3.0], [-0.3, 0.4], samples=101))
    (leg,) = fig.legends
    modes = [c[0].mode for c, _ in _key_parts(leg) if isinstance(c[0], ModeSwatch)]
    assert modes == list(MAP_MODES)
    assert Mode.SRO_PRIME_MINUS in modes
