"""regimemap.maps.figures.mapplot: fills where the modes are, vector and byte-stable output, no pyplot."""

from __future__ import annotations

import io
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections import Counter

import numpy as np
import pytest

from regimemap import MAP_MODES, Mode, Parameters, label_grid
from regimemap.drawing.artists import MapArtists
from regimemap.drawing.save import FORMATS, format_from_path, save_figure
from regimemap.drawing.style import MODE_STYLE
from regimemap.maps.figures.figure import map_figure, new_figure, render_map, render_preset
from regimemap.maps.figures.mapplot import MapStyle, draw_design_points, draw_map
from regimemap.maps.figures.presets import PRESETS, get_preset
from regimemap.maps.file_points import DesignPoint
from regimemap.maps.mapdata import map_for_view
from regimemap.maps.run import run_map

pytestmark = pytest.mark.render

ALL_MODE_IDS = ("3.9a", "3.9b", "3.10", "3.11", "4.7a", "4.7b")


def _rgb(color: str) -> np.ndarray:
    from matplotlib.colors import to_rgb

    return np.round(np.array(to_rgb(color)) * 255).astype(int)


def _deep_points(pr, n_k=160, n_mu=120):
    """For each mode of a final map: the grid point farthest (in grid cells) from any other mode."""
    from regimemap.maps.view import auto_extent

    k_max, mu_max = auto_extent(pr.params, k_max=pr.k_max, mu_max=pr.mu_max)
    k = (np.arange(n_k) + 0.5) / n_k * k_max
    mu = (np.arange(n_mu) + 0.5) / n_mu * mu_max
    grid = label_grid(k, mu, pr.gamma, pr.kprime)  # rows mu, columns k
    out = {}
    for mode in MAP_MODES:
        inside = grid == mode
        if not inside.any():
            continue
        depth = np.zeros(grid.shape, dtype=int)
        cur = inside.copy()
        d = 0
        while cur.any():  # erosion: depth = distance (cells) to another mode or the frame
            d += 1
            depth[cur] = d
            shrunk = cur.copy()
            shrunk[1:, :] &= cur[:-1, :]
            shrunk[:-1, :] &= cur[1:, :]
            shrunk[:, 1:] &= cur[:, :-1]
            shrunk[:, :-1] &= cur[:, 1:]
            shrunk[0, :] = shrunk[-1, :] = False
            shrunk[:, 0] = shrunk[:, -1] = False
            cur = shrunk
        i, j = np.unravel_index(np.argmax(np.where(inside, depth, 0)), grid.shape)
        out[Mode(mode)] = (k[j], mu[i], int(depth[i, j]))
    return out, (k_max, mu_max)


def _pixel_patch(fig, ax, k, mu, half=2):
    fig.canvas.draw()
    buf = np.asarray(fig.canvas.buffer_rgba())
    x, y = ax.transData.transform((k, mu))
    h = buf.shape[0]
    col, row = int(round(x)), int(round(h - y))
    patch = buf[row - half:row + half + 1, col - half:col + half + 1, :3]
    return patch.reshape(-1, 3)


@pytest.mark.parametrize("fid", ALL_MODE_IDS)
def test_fill_colour_inside_each_region(fid):
    """Render the all-mode figure (no hatches, no decorations) and read the colour of each region."""
    pr = PRESETS[fid]
    deep, (k_max, mu_max) = _deep_points(pr)
    fig, ax, art = map_figure(run_map(pr.params, k_max=k_max, mu_max=mu_max, modes=pr.modes, curves=False), dpi=60,
                              curves=False, hatches=False, labels=False, legend=False, title="")
    assert deep, "no region found"
    checked = 0
    for mode, (k, mu, depth) in deep.items():
        if depth < 3:
            continue  # a sliver: too thin to sample at this resolution
        patch = _pixel_patch(fig, ax, k, mu, half=1)
        want = _rgb(MODE_STYLE[mode].color)
        assert np.abs(patch - want).max() <= 2, (fid, mode.label, patch[0], want)
        checked += 1
    assert checked >= max(len(deep) - 1, 1)


@pytest.mark.parametrize("fid", ["3.9a", "3.11", "4.7a"])
def test_most_common_colour_with_hatches_and_labels(fid):
    """With hatches, lines and labels on, the dominant colour near a deep point is the fill."""
    pr = PRESETS[fid]
    deep, (k_max, mu_max) = _deep_points(pr)
    fig, ax, art = map_figure(run_map(pr.params, k_max=k_max, mu_max=mu_max, modes=pr.modes), dpi=100, labels=False)
    for mode, (k, mu, depth) in deep.items():
        if depth < 4:
            continue
        patch = _pixel_patch(fig, ax, k, mu, half=4)
        common, _ = Counter(map(tuple, patch)).most_common(1)[0]
        want = _rgb(MODE_STYLE[mode].color)
        assert np.abs(np.array(common) - want).max() <= 2, (fid, mode.label, common, want)


@pytest.mark.deep
def test_region_labels_are_in_their_regions():
    from regimemap import classify

    for fid in ALL_MODE_IDS:
        pr = PRESETS[fid]
        fig, ax, art = map_figure(run_map(pr.params, k_max=pr.k_max, mu_max=pr.mu_max, modes=pr.modes))
        for mode, texts in art.region_labels.items():
            for t in texts:
                k, mu = getattr(t, "xy", None) or t.get_position()  # leader labels point in
                assert classify(k, mu, pr.gamma, pr.kprime) == mode, (fid, mode.label)


def test_draw_map_returns_what_it_drew():
    fig, ax = new_figure()
    art = draw_map(ax, map_for_view(Parameters(3.0, 0.4)))
    assert isinstance(art, MapArtists)
    assert set(art.fills) == set(MAP_MODES)
    assert art.fills[Mode.RO] and art.fills[Mode.RO][0].axes is ax
    assert not art.fills[Mode.SRO_PLUS]  # case 1: no SRO+
    assert {"OA", "AB", "CD", "mu_star"} <= set(art.curves)
    assert "mu_star" in art.curve_labels
    assert {"O", "A", "C", "D"} <= set(art.point_labels)
    assert art.legend is not None and art.title is not None
    assert art.polygons is art.data.polygons
    k_max, mu_max = art.extent
    assert ax.get_xlim() == (0.0, k_max) and ax.get_ylim() == (0.0, mu_max)
    # fills under the curves, curves under the labels
    z_fill = max(p.get_zorder() for ps in art.fills.values() for p in ps)
    z_line = min(ln.get_zorder() for ls in art.curves.values() for ln in ls)
    assert z_fill < z_line
    assert ax.get_xlabel() == "$k$" and ax.get_ylabel() == r"$\mu$"


def test_draw_map_options():
    fig, ax = new_figure()
    data = map_for_view(Parameters(3.0, 0.4), modes=[Mode.RO], curves=False, k_max=2.0, mu_max=1.0)
    art = draw_map(ax, data, MapStyle(curves=False, labels=False, legend=False, title=""))
    assert set(art.fills) == {Mode.RO}
    assert not art.curves and not art.region_labels and art.legend is None
    assert art.title is None and ax.get_title(loc="left") == ""
    assert art.extent == (2.0, 1.0)


def test_draw_on_a_user_axes_with_subplots():
    """draw_map works on any Axes (no layout of its own)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10, 4))
    FigureCanvasAgg(fig)
    a1, a2 = fig.subplots(1, 2)
    draw_map(a1, map_for_view(Parameters(3.0, 0.2)), MapStyle(legend=False))
    draw_map(a2, map_for_view(Parameters(3.0, -0.3)), MapStyle(legend=False))
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    assert buf.getvalue().startswith(b"\x89PNG")


def test_design_points():
    fig, ax = new_figure()
    draw_map(ax, map_for_view(Parameters(3.0, 0.4)))
    pts = [DesignPoint(0.45, 0.3, "caisson-A"), DesignPoint(0.2, 0.1, "")]
    arts = draw_design_points(ax, pts)
    assert len(arts) == 2  # one marker line + one name (the unnamed point has none)
    assert arts[1].get_text() == "caisson-A"
    assert arts[0].get_zorder() > 4
    assert draw_design_points(ax, []) == []


def test_design_points_extend_the_view():
    fig, ax, art = map_figure(run_map(Parameters(3.0, 0.4), points=[DesignPoint(3.0, 2.0, "far")]))
    assert art.extent[0] > 3.0 and art.extent[1] > 2.0


def _preset_map(fid):
    """The map of one of the report's figures, as ``regimemap figure`` computes it."""
    return run_map(**get_preset(fid).map_keywords)


def _render_bytes(fmt, fid=None):
    fig = (render_preset(fid, _preset_map(fid), dpi=50) if fid
           else render_map(run_map(Parameters(3.0, 0.4)), dpi=50))
    buf = io.BytesIO()
    from regimemap.drawing.save import metadata as _metadata
    from regimemap.drawing.style import style_context

    with style_context():
        fig.savefig(buf, format=fmt, dpi=50, metadata=_metadata(fmt))
    return buf.getvalue()


@pytest.mark.parametrize("fmt", FORMATS)
def test_two_renders_are_byte_identical(fmt, tmp_path):
    a, b = tmp_path / f"a.{fmt}", tmp_path / f"b.{fmt}"
    save_figure(render_map(run_map(Parameters(3.0, 0.4))), a)
    save_figure(render_map(run_map(Parameters(3.0, 0.4))), b)
    assert a.read_bytes() == b.read_bytes()


@pytest.mark.deep
def test_reused_figure_gives_the_same_bytes(tmp_path):
    fig = None
    for fid in ("3.9a", "4.7a", "3.10"):
        fig = render_preset(fid, _preset_map(fid), fig=fig)
    save_figure(fig, tmp_path / "reused.svg")
    save_figure(render_preset("3.10", _preset_map("3.10")), tmp_path / "fresh.svg")
    assert (tmp_path / "reused.svg").read_bytes() == (tmp_path / "fresh.svg").read_bytes()


def test_png_output(tmp_path):
    from PIL import Image

    path = save_figure(render_map(run_map(Parameters(3.0, 0.4))), tmp_path / "m.png")
    data = path.read_bytes()
    assert data.startswith(b"\x89PNG\r\n\x1a\n")
    im = Image.open(path)
    assert im.info.get("Software", "").startswith("regimemap")
    assert im.size[0] == 960  # 6.4 in at 150 dpi


def test_svg_output_is_vector_small_and_dateless(tmp_path):
    path = save_figure(render_map(run_map(Parameters(3.0, 0.4))), tmp_path / "m.svg")
    data = path.read_bytes()
    assert len(data) < 1_000_000
    root = ET.fromstring(data)
    ns = "{http://www.w3.org/2000/svg}"
    assert root.tag == f"{ns}svg"
    assert not root.findall(f".//{ns}image"), "raster image in the SVG"
    assert b"<dc:date>" not in data
    assert b"regimemap" in data  # Creator


def test_pdf_output_has_truetype_fonts_and_no_raster(tmp_path):
    path = save_figure(render_map(run_map(Parameters(3.0, -0.3))), tmp_path / "m.pdf")
    data = path.read_bytes()
    assert data.startswith(b"%PDF")
    assert b"/Type3" not in data and b"/Subtype /Type3" not in data
    assert b"/CIDFontType2" in data or b"/TrueType" in data
    assert b"/Subtype /Image" not in data
    assert b"/CreationDate" not in data


def test_save_figure_rejects_unknown_formats_and_leaves_nothing(tmp_path):
    fig = render_map(run_map(Parameters(3.0, 0.4)), dpi=40)
    with pytest.raises(ValueError, match=r"unknown file suffix \.jpg .*use \.png, \.svg or \.pdf"):
        save_figure(fig, tmp_path / "m.jpg")
    with pytest.raises(ValueError, match="png, svg, pdf"):
        save_figure(fig, tmp_path / "m.png", fmt="gif")
    assert list(tmp_path.iterdir()) == []


def test_save_figure_is_atomic(tmp_path, monkeypatch):
    fig = render_map(run_map(Parameters(3.0, 0.4)), dpi=40)
    target = tmp_path / "m.png"
    target.write_bytes(b"old")

    def boom(*args, **kwargs):
        raise OSError("disk full")

    monkeypatch.setattr(fig, "savefig", boom)
    with pytest.raises(OSError):
        save_figure(fig, target)
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["m.png"]


def test_format_from_path():
    assert format_from_path("a.SVG") == "svg"
    assert format_from_path("a", "pdf") == "pdf"
    assert format_from_path("a.png", "png") == "png"
    with pytest.raises(ValueError):
        format_from_path("a")
    with pytest.raises(ValueError):
        format_from_path("a.svg", "png")


def test_mode_styles_are_distinct_and_light():
    from matplotlib.colors import to_rgb

    colours = [MODE_STYLE[m].color for m in MAP_MODES]
    hatches = [MODE_STYLE[m].hatch for m in MAP_MODES]
    assert len(set(colours)) == len(colours)
    assert len(set(hatches)) == len(hatches) and all(hatches)

    def luminance(c):
        rgb = np.array(to_rgb(c))
        lin = np.where(rgb <= 0.03928, rgb / 12.92, ((rgb + 0.055) / 1.055) ** 2.4)
        return 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2]

    for c in colours:  # black text and lines on every fill: WCAG contrast >= 7
        assert (luminance(c) + 0.05) / 0.05 >= 7.0, c


@pytest.mark.subprocess
def test_no_pyplot_and_no_global_rcparams():
    code = (
        "import matplotlib, sys\n"
        "rc = matplotlib.rcParams\n"
        "keys = [k for k in rc if k != 'backend']  # reading 'backend' would import pyplot\n"
        "before = {k: rc[k] for k in keys}\n"
        "from regimemap import Parameters\n"
        "from regimemap.maps.figures.figure import render_map\nfrom regimemap.drawing.save import save_figure\n"
        "import io\n"
        "from regimemap.maps.run import run_map\n"
        "fig = render_map(run_map(Parameters(3, 0.4)), dpi=40)\n"
        "fig.savefig(io.BytesIO(), format='svg')\n"
        "changed = [k for k in keys if rc[k] != before[k]]\n"
        "print('pyplot' if 'matplotlib.pyplot' in sys.modules else 'no-pyplot', changed)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "no-pyplot []"


def test_mathtext_parses_are_shared_between_renderers():
    """Each SVG file has a renderer and a mathtext parser of its own: a formula is parsed once."""
    from matplotlib.mathtext import MathTextParser

    from regimemap.drawing.style import share_mathtext_parses, style_context

    with style_context():
        pass
    assert getattr(MathTextParser.__dict__["_parse_cached"], "regimemap_shared", False)
    assert not share_mathtext_parses()  # installed once per process
    one, other = MathTextParser("path"), MathTextParser("path")
    assert one.parse(r"$\mu^*(k)$", 72) is other.parse(r"$\mu^*(k)$", 72)
    assert type(MathTextParser("agg").parse(r"$\mu^*(k)$", 72)).__name__ == "RasterParse"



@pytest.mark.subprocess
@pytest.mark.skipif(not hasattr(os, "fork"), reason="workers are forked on POSIX only")
def test_a_forked_worker_starts_with_no_parse_of_its_parent():
    """A parse keeps the fonts it was laid out with, whose files a fork shares with the parent
    through one offset (two processes reading glyphs at once read each other's bytes: "too many
    hints"): a forked process starts with the mathtext cache empty; the parent keeps its own."""
    from matplotlib.mathtext import MathTextParser

    from regimemap.drawing.style import style_context

    with style_context():
        pass
    parser = MathTextParser("path")
    first = parser.parse(r"$\mu^*(k_{B'})$", 72)
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: a parse of its own, not the parent's object
        try:
            fresh = MathTextParser("path").parse(r"$\mu^*(k_{B'})$", 72) is not first
            os.write(write, b"fresh" if fresh else b"inherited")
        finally:
            os._exit(0)
    os.close(write)
    with os.fdopen(read) as pipe:
        said = pipe.read()
    os.waitpid(pid, 0)
    assert said == "fresh"
    assert parser.parse(r"$\mu^*(k_{B'})$", 72) is first  # the parent's cache is kept


# -- names of the points ------------------------------------------------------------------


@pytest.mark.parametrize("gamma", [1.0, 3.0, 4.0, 6.0])
@pytest.mark.deep
def test_point_names_never_overlap(gamma):
    """E and F (and D, G) on the k axis can nearly coincide; their names must not."""
    import itertools

    for kprime in (-0.6, -0.3, -0.2, -0.1, 0.0, 0.2, 0.4, 0.85):
        fig, ax, art = map_figure(run_map(Parameters(gamma, kprime)), dpi=72)
        fig.draw_without_rendering()  # laid out as drawn (the same boxes), without the pixels
        r = fig.canvas.get_renderer()
        boxes = {n: t.get_window_extent(r) for n, t in art.point_labels.items()}
        for a, b in itertools.combinations(boxes, 2):
            A, B = boxes[a], boxes[b]
            overlap_x = min(A.x1, B.x1) - max(A.x0, B.x0)
            overlap_y = min(A.y1, B.y1) - max(A.y0, B.y0)
            assert overlap_x <= 0.5 or overlap_y <= 0.5, (gamma, kprime, a, b)


def test_point_offsets_for_crowded_axis_points():
    from types import SimpleNamespace as P

    from regimemap.drawing.text.labels import ABOVE as _ABOVE
    from regimemap.drawing.text.labels import LEFT_OF as _LEFT_OF
    from regimemap.drawing.text.labels import POINT_OFFSET as _POINT_OFFSET
    from regimemap.drawing.text.labels import RIGHT_OF as _RIGHT_OF
    from regimemap.drawing.text.labels import point_offsets as _point_offsets

    frame = P(k_max=1.0, w_pt=400.0)  # 1 unit of k = 400 points
    pts = {"O": P(k=0.0, mu=0.0), "F": P(k=0.50, mu=0.0), "E": P(k=0.51, mu=0.0),
           "D": P(k=0.52, mu=0.0), "G": P(k=0.9, mu=0.0), "A": P(k=0.5, mu=0.5)}
    off = _point_offsets(pts, frame)
    assert off["F"] == _LEFT_OF and off["E"] == _ABOVE and off["D"] == _RIGHT_OF
    assert off["G"] == _POINT_OFFSET["G"] and off["A"] == _POINT_OFFSET["A"]
    assert off["O"] == _POINT_OFFSET["O"]
    # E right of F: the order decides, not the name
    off = _point_offsets({"E": P(k=0.50, mu=0.0), "F": P(k=0.51, mu=0.0)}, frame)
    assert off["E"] == _LEFT_OF and off["F"] == _RIGHT_OF
    # no room on the left inside the axes: above instead
    off = _point_offsets({"F": P(k=0.01, mu=0.0), "E": P(k=0.02, mu=0.0)}, frame)
    assert off["F"] == _ABOVE and off["E"] == _RIGHT_OF
