"""``regimemap explore`` and :class:`regimemap.maps.figures.explore.explorer.Explorer`, under Agg.

The widgets' callbacks call plain methods (set_gamma, set_kprime, set_loads,
click, save); the tests drive those methods and, through synthetic mouse
events, the widgets themselves, and check each redrawn map against what
``regimemap plot`` draws at the same parameters: the same region polygons
(exact arrays), the same answer as ``regimemap classify`` at a clicked point,
and the same file bytes from Save.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from regimemap import Parameters
from regimemap.cli.explore import open_explorer, plot_command_line
from regimemap.maps.figures.explore.explorer import Explorer
from regimemap.maps.figures.explore.images import KeyImage, TextPanel, WidgetsImage
from regimemap.maps.figures.figure import map_figure
from regimemap.maps.mapdata import map_for_view
from regimemap.maps.query import classify_point
from regimemap.maps.run import run_map
from regimemap.mechanics.modes import Mode

pytestmark = pytest.mark.render


class Echo:
    """Collects what the explorer prints (stdout lines and stderr notes apart)."""

    def __init__(self) -> None:
        self.out: list[str] = []
        self.err: list[str] = []

    def __call__(self, text: str, err: bool = False) -> None:
        (self.err if err else self.out).append(text)


@pytest.fixture
def echo() -> Echo:
    return Echo()


@pytest.fixture
def explorer(echo: Echo):
    ex = open_explorer(Parameters(3.0, 0.4), echo=echo)
    yield ex
    ex.close()


def plot_polygons(params: Parameters, point: tuple[float, float] | None = None,
                  resolution: int = 801) -> dict[Mode, list[np.ndarray]]:
    """The polygons ``regimemap plot`` fills (its own call of map_figure)."""
    from regimemap.maps.points import DesignPoint

    points = [DesignPoint(*point)] if point is not None else []
    _, _, art = map_figure(run_map(params, points=points, samples=resolution, view="designer"), dpi=150)
    return art.data.polygons


def assert_same_map(ex: Explorer, params: Parameters) -> None:
    """The explorer shows ``params`` with plot's polygons, and its patches are exactly them."""
    assert ex.params == params
    want = plot_polygons(params, None if ex.point is None else (ex.point.k, ex.point.mu),
                         ex.resolution)
    got = ex.artists.data.polygons
    assert list(got) == list(want)
    for mode in want:
        assert len(got[mode]) == len(want[mode])
        for a, b in zip(got[mode], want[mode]):
            np.testing.assert_array_equal(a, b)
        drawn = [p for p in want[mode] if len(p) >= 3]
        patches = ex.artists.fills[mode]
        assert len(patches) == len(drawn)
        for patch, poly in zip(patches, drawn):
            assert patch.axes is ex.ax  # on the map, not a left-over
            np.testing.assert_array_equal(patch.get_xy()[: len(poly)], poly)
    # nothing of an earlier map is left on the axes
    assert len(ex.ax.patches) == sum(len(v) for v in ex.artists.fills.values())


# -- the map follows the sliders ------------------------------------------------------------------


def test_initial_map_is_plots(explorer: Explorer) -> None:
    assert_same_map(explorer, Parameters(3.0, 0.4))
    assert explorer.ax.get_legend() is explorer.artists.legend
    assert explorer.artists.legend is not None and explorer.artists.legend.get_visible()


@pytest.mark.parametrize("final", [True, False], ids=["from code", "while dragging"])
@pytest.mark.deep
def test_set_gamma_and_kprime_redraw_plots_map(explorer: Explorer, final: bool) -> None:
    explorer.set_gamma(2.5, final=final)
    assert_same_map(explorer, Parameters(2.5, 0.4))
    explorer.set_kprime(-0.3, final=final)
    assert_same_map(explorer, Parameters(2.5, -0.3))
    explorer.set_kprime(0.85, final=final)
    assert_same_map(explorer, Parameters(2.5, 0.85))
    explorer.finish()
    assert_same_map(explorer, Parameters(2.5, 0.85))


@pytest.mark.deep
def test_values_are_rounded_as_the_sliders_show_them(explorer: Explorer) -> None:
    explorer.set_gamma(2.54321)
    explorer.set_kprime(-0.30049)
    assert explorer.params == Parameters(2.54, -0.3)
    assert explorer.gamma_slider.valtext.get_text() == "2.54"
    assert explorer.kprime_slider.valtext.get_text() == "-0.3"
    assert math.isclose(10.0 ** explorer.gamma_slider.val, 2.54)
    explorer.set_kprime(-0.0001)
    assert explorer.params.kprime == 0.0 and math.copysign(1.0, explorer.params.kprime) == 1.0


@pytest.mark.deep
def test_set_loads_and_the_toggle(explorer: Explorer) -> None:
    assert not explorer.loads_enabled and not explorer.buoyancy_slider.ax.get_visible()
    explorer.set_loads(buoyancy=0.3, uplift_ratio=0.5)
    assert explorer.loads_enabled and explorer.loads_check.get_status() == [True]
    assert explorer.buoyancy_slider.ax.get_visible() and explorer.nu_slider.ax.get_visible()
    assert_same_map(explorer, Parameters(3.0, 0.4, buoyancy=0.3, uplift_ratio=0.5))
    assert Mode.LO in explorer.artists.data.modes
    explorer.set_loads(enabled=False)  # back to the report's block; the values are kept
    assert explorer.loads_check.get_status() == [False]
    assert not explorer.buoyancy_slider.ax.get_visible()
    assert_same_map(explorer, Parameters(3.0, 0.4))
    explorer.set_loads(enabled=True)
    assert_same_map(explorer, Parameters(3.0, 0.4, buoyancy=0.3, uplift_ratio=0.5))
    explorer.set_loads(uplift_ratio=0.0, final=False)
    assert_same_map(explorer, Parameters(3.0, 0.4, buoyancy=0.3))


def test_ticking_loads_shows_their_sliders_at_once(explorer: Explorer, monkeypatch) -> None:
    """Ticking 'loads' with both sliders at 0 changes no map, yet their sliders appear: the figure
    is redrawn at once (not only after the next drag of gamma)."""
    import regimemap.maps.figures.explore.explorer as explore_module

    draws: list[object] = []
    monkeypatch.setattr(explore_module, "request_draw", draws.append)
    assert not explorer.buoyancy_slider.ax.get_visible()
    before = explorer.params
    explorer.loads_check.set_active(0)  # what a click on the box does
    assert explorer.loads_enabled and explorer.params == before  # the same block: beta = nu = 0
    assert explorer.buoyancy_slider.ax.get_visible() and explorer.nu_slider.ax.get_visible()
    assert draws == [explorer.fig]
    explorer.loads_check.set_active(0)  # and unticking hides them, drawn at once too
    assert not explorer.buoyancy_slider.ax.get_visible() and draws == [explorer.fig, explorer.fig]


@pytest.mark.deep
def test_loads_given_at_start(echo: Echo) -> None:
    p = Parameters(0.7, -0.018, buoyancy=0.318, uplift_ratio=0.524, gyration=0.8)
    ex = open_explorer(p, echo=echo)
    try:
        assert ex.loads_enabled and ex.buoyancy_slider.valtext.get_text() == "0.318"
        assert_same_map(ex, p)
        ex.set_loads(enabled=False)  # the gyration is not a slider's: it stays
        assert_same_map(ex, Parameters(0.7, -0.018, gyration=0.8))
    finally:
        ex.close()


def test_a_refused_value_changes_nothing(explorer: Explorer) -> None:
    before = explorer.params
    with pytest.raises(ValueError, match="buoyancy"):
        explorer.set_loads(buoyancy=1.0)
    with pytest.raises(ValueError, match="gamma"):
        explorer.set_gamma(0.0)
    assert explorer.params == before and not explorer.loads_enabled
    assert_same_map(explorer, before)


@pytest.mark.deep
def test_drag_then_release(explorer: Explorer) -> None:
    """While dragging: no tidy pass, the key from its bitmap; the release completes the map."""
    explorer.click(0.45, 0.6)
    panel_before = explorer.info_text
    explorer.set_gamma(2.0, final=False)
    legend = explorer.ax.get_legend()
    assert legend is not None and not legend.get_visible()
    assert explorer._key.shown  # noqa: SLF001 - the bitmap of the key is drawn instead
    assert "released" in explorer.info_text and explorer.info_text != panel_before
    explorer.fig.canvas.draw()
    explorer.finish()
    legend = explorer.ax.get_legend()
    assert legend is not None and legend.get_visible() and not explorer._key.shown  # noqa: SLF001
    assert explorer.result is not None and explorer.result.gamma == 2.0
    assert explorer.info_text == explorer.describe(explorer.result)


def test_key_bitmap_is_rendered_once_per_content(explorer: Explorer) -> None:
    key: KeyImage = explorer._key  # noqa: SLF001
    for g in (3.1, 3.2, 3.3, 3.4):
        explorer.set_gamma(g, final=False)
        explorer.fig.canvas.draw()
    assert key.renders == 1  # the same modes in view: one bitmap for the whole drag
    explorer.set_loads(buoyancy=0.3, uplift_ratio=1.0, final=False)  # lift-off joins the key
    assert key.renders == 2


def test_key_bitmap_shows_the_key(explorer: Explorer) -> None:
    canvas = explorer.fig.canvas
    explorer.set_gamma(2.2)
    canvas.draw()
    real = np.asarray(canvas.buffer_rgba()).copy()
    explorer.set_gamma(2.2, final=False)  # the same map, its key from the bitmap
    explorer.set_gamma(2.3, final=False)
    explorer.set_gamma(2.2, final=False)
    canvas.draw()
    cached = np.asarray(canvas.buffer_rgba()).copy()
    legend = explorer.ax.get_legend()
    assert legend is not None
    box = legend.get_window_extent()
    h = real.shape[0]
    rows = slice(int(h - box.y1), int(h - box.y0))
    cols = slice(int(box.x0), int(box.x1))
    assert np.abs(real[rows, cols].astype(int) - cached[rows, cols].astype(int)).max() <= 2


@pytest.mark.deep
def test_still_widgets_are_drawn_from_bitmaps_while_dragging(explorer: Explorer) -> None:
    """While one slider is dragged the other widgets are pixels (the same); the release shows them."""
    still: WidgetsImage = explorer._still  # noqa: SLF001
    canvas = explorer.fig.canvas
    explorer.set_loads(buoyancy=0.2)
    canvas.draw()
    real = np.asarray(canvas.buffer_rgba()).copy()
    widgets = [explorer.kprime_slider.ax, explorer.buoyancy_slider.ax, explorer.nu_slider.ax,
               explorer.save_ax]
    boxes = [ax.get_tightbbox() for ax in widgets]
    for g in (3.1, 3.2, 3.0):
        explorer.set_gamma(g, final=False)
        canvas.draw()
    assert set(still.frozen) == set(widgets) and explorer.gamma_slider.ax.get_visible()
    assert explorer.check_ax.get_visible()  # its mark is drawn by the widget itself
    assert not any(ax.get_visible() for ax in widgets)
    assert still.renders == len(widgets)  # once each for the whole drag
    cached = np.asarray(canvas.buffer_rgba()).copy()
    h = real.shape[0]
    for box in boxes:
        rows = slice(int(h - box.y1), int(h - box.y0))
        cols = slice(int(box.x0), int(box.x1))
        assert np.abs(real[rows, cols].astype(int) - cached[rows, cols].astype(int)).max() <= 2
    explorer.finish()
    assert still.frozen == () and all(ax.get_visible() for ax in widgets)
    # a drag of k' next: the gamma slider is frozen, k' is not; unchanged widgets stay cached
    explorer.set_kprime(0.3, final=False)
    assert explorer.gamma_slider.ax in still.frozen and explorer.kprime_slider.ax not in still.frozen
    assert still.renders == len(widgets) + 1
    # the loads switched off meanwhile: their sliders are hidden, not frozen
    explorer.set_loads(enabled=False, final=False)
    assert not explorer.buoyancy_slider.ax.get_visible()
    assert explorer.buoyancy_slider.ax not in still.frozen
    explorer.finish()
    assert not explorer.buoyancy_slider.ax.get_visible() and explorer.kprime_slider.ax.get_visible()


# -- a click: what classify says -------------------------------------------------------------------


def classify_text(run_cli, params: Parameters, k: float, mu: float) -> str:
    args = ["classify", "--gamma", repr(params.gamma), "--kprime", repr(params.kprime),
            "--k", repr(k), "--mu", repr(mu)]
    for name, value in params.loads.items():
        if value is not None and name in ("buoyancy", "uplift_ratio") and value != 0.0:
            args += [f"--{name.replace('_', '-')}", repr(value)]
    run = run_cli(args)
    assert run.code == 0, run.stderr
    return run.stdout.rstrip("\n")


def test_click_shows_and_prints_classifys_answer(explorer: Explorer, echo: Echo, run_cli) -> None:
    res = explorer.click(0.45, 0.6)
    assert (res.k, res.mu, res.mode) == (0.45, 0.6, Mode.RO)
    text = classify_text(run_cli, explorer.params, 0.45, 0.6)
    assert explorer.info_text == text
    assert explorer._info.get_text() == text  # noqa: SLF001 - the panel on the figure
    assert echo.out[-1] == text
    dots = [a for a in explorer.artists.extra if a.get_gid() == "design-dots"]
    assert len(dots) == 1 and list(dots[0].get_xdata()) == [0.45]
    assert_same_map(explorer, Parameters(3.0, 0.4))


@pytest.mark.deep
def test_click_follows_the_sliders_and_the_loads(explorer: Explorer, run_cli) -> None:
    explorer.click(2.3456789, 0.77777)
    pt = explorer.point
    assert pt is not None and (pt.k, pt.mu) == (2.346, 0.778)  # 1/1000 of the view (k <= 1)
    assert explorer.artists.data.k_max >= 2.346  # the view grows to show it, as plot does
    explorer.set_kprime(-0.6)
    assert explorer.info_text == classify_text(run_cli, explorer.params, pt.k, pt.mu)
    explorer.set_loads(buoyancy=0.318, uplift_ratio=0.524)
    assert explorer.result is not None and explorer.result.loads["buoyancy"] == 0.318
    assert explorer.info_text == classify_text(run_cli, explorer.params, pt.k, pt.mu)
    assert_same_map(explorer, Parameters(3.0, -0.6, buoyancy=0.318, uplift_ratio=0.524))


@pytest.mark.deep
def test_panel_text_is_rendered_once_per_text(explorer: Explorer) -> None:
    panel: TextPanel = explorer._info  # noqa: SLF001
    explorer.click(0.45, 0.6)
    canvas = explorer.fig.canvas
    canvas.draw()
    n = panel.renders
    for g in (3.1, 3.2, 3.3):
        explorer.set_gamma(g, final=False)  # the panel waits: one short note
        canvas.draw()
    assert panel.renders == n + 1
    canvas.draw()
    assert panel.renders == n + 1


def test_clear_point(explorer: Explorer) -> None:
    explorer.click(0.45, 0.6)
    explorer.clear_point()
    assert explorer.point is None and explorer.result is None
    assert "Click on the map" in explorer.info_text
    assert not [a for a in explorer.artists.extra if a.get_gid() == "design-dots"]


# -- Save: plot's bytes ------------------------------------------------------------------------------


def plot_bytes(run_cli, tmp_path: Path, args: list[str], name: str) -> bytes:
    out = tmp_path / "plot" / name
    out.parent.mkdir(exist_ok=True)
    run = run_cli(["plot", *args, "-o", str(out)])
    assert run.code == 0, run.stderr
    return out.read_bytes()


@pytest.mark.deep
def test_save_writes_plots_bytes_and_name(explorer: Explorer, echo: Echo, run_cli,
                                          tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    explorer.set_gamma(2.5)
    explorer.set_kprime(-0.3)
    path = explorer.save()
    assert path == Path("regime-g2.5-kp-0.3.png")  # plot's default name, in the current folder
    assert echo.out[-1] == str(path)
    assert path.read_bytes() == plot_bytes(run_cli, tmp_path, ["--gamma", "2.5", "--kprime", "-0.3"],
                                           "a.png")
    assert echo.err[-1].endswith("regimemap plot --gamma 2.5 --kprime -0.3")


@pytest.mark.slow
@pytest.mark.deep
def test_save_with_loads_and_a_point(explorer: Explorer, run_cli, tmp_path: Path,
                                     monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    explorer.set_loads(buoyancy=0.3, uplift_ratio=0.5)
    explorer.click(0.45, 0.6)
    path = explorer.save()
    assert path == Path("regime-g3-kp0.4-b0.3-nu0.5.png")
    args = ["--gamma", "3", "--kprime", "0.4", "--buoyancy", "0.3", "--uplift-ratio", "0.5",
            "--point", "0.45,0.6"]
    assert path.read_bytes() == plot_bytes(run_cli, tmp_path, args, "b.png")
    assert plot_command_line(explorer) == ("regimemap plot --gamma 3.0 --kprime 0.4 --buoyancy 0.3 "
                                           "--uplift-ratio 0.5 --point 0.45,0.6")
    svg = explorer.save(tmp_path / "view.svg")
    assert svg.read_bytes() == plot_bytes(run_cli, tmp_path, args, "b.svg")


@pytest.mark.deep
def test_save_at_another_resolution(echo: Echo, run_cli, tmp_path: Path) -> None:
    ex = open_explorer(Parameters(3.0, -0.2), resolution=300, echo=echo)
    try:
        assert_same_map(ex, Parameters(3.0, -0.2))
        path = ex.save(tmp_path / "r.png")
        args = ["--gamma", "3", "--kprime", "-0.2", "--resolution", "300"]
        assert path.read_bytes() == plot_bytes(run_cli, tmp_path, args, "r.png")
        assert plot_command_line(ex).endswith("--resolution 300")
    finally:
        ex.close()


@pytest.mark.deep
def test_standalone_explorer_defaults(tmp_path: Path, monkeypatch, run_cli) -> None:
    """Without the command line's wiring: classify's text, plot's bytes, a plain file name."""
    lines: list[str] = []
    ex = Explorer(Parameters(3.0, 0.4), compute=map_for_view, classify=classify_point, echo=lines.append)
    try:
        ex.click(0.45, 0.6)
        text = classify_text(run_cli, Parameters(3.0, 0.4), 0.45, 0.6)
        assert ex.info_text == text and lines == [text]
        monkeypatch.chdir(tmp_path)
        path = ex.save()
        assert path == Path("regime-g3-kp0.4.png")
        assert path.read_bytes() == plot_bytes(
            run_cli, tmp_path, ["--gamma", "3", "--kprime", "0.4", "--point", "0.45,0.6"], "c.png")
        assert repr(ex) == "<Explorer gamma=3, k'=0.4; point k=0.45, mu=0.6>"
        ex.set_loads(buoyancy=0.3)
        assert ex.save().name == "regime-g3-kp0.4-loaded.png"
    finally:
        ex.close()


# -- the widgets themselves, through mouse events ------------------------------------------------


def mouse(ex: Explorer, name: str, ax, x: float, y: float) -> None:
    """A mouse event at data coordinates (x, y) of ``ax`` (axes fractions for the check
    box and the button), through the canvas's callbacks."""
    from matplotlib.backend_bases import MouseEvent

    trans = ax.transAxes if ax in (ex.check_ax, ex.save_ax) else ax.transData
    px, py = trans.transform((x, y))
    event = MouseEvent(name, ex.fig.canvas, px, py, button=1)
    ex.fig.canvas.callbacks.process(name, event)


@pytest.mark.slow
@pytest.mark.deep
def test_widgets_call_the_methods(explorer: Explorer, echo: Echo, tmp_path: Path,
                                  monkeypatch) -> None:
    ex = explorer
    # drag the gamma slider (log10 scale) from 3 to 2, then release
    s = ex.gamma_slider
    mouse(ex, "button_press_event", s.ax, math.log10(3.0), 0.5)
    mouse(ex, "motion_notify_event", s.ax, math.log10(2.5), 0.5)
    assert ex.params.gamma == 2.5 and ex._key.shown  # noqa: SLF001 - dragging
    mouse(ex, "motion_notify_event", s.ax, math.log10(2.0), 0.5)
    mouse(ex, "button_release_event", s.ax, math.log10(2.0), 0.5)
    assert ex.params == Parameters(2.0, 0.4) and not ex._key.shown  # noqa: SLF001
    assert_same_map(ex, Parameters(2.0, 0.4))
    # the k' slider: a click sets it
    mouse(ex, "button_press_event", ex.kprime_slider.ax, -0.5, 0.5)
    mouse(ex, "button_release_event", ex.kprime_slider.ax, -0.5, 0.5)
    assert ex.params == Parameters(2.0, -0.5)
    # the toggle, then the buoyancy slider
    mouse(ex, "button_press_event", ex.check_ax, 0.15, 0.5)  # the box
    mouse(ex, "button_release_event", ex.check_ax, 0.15, 0.5)
    assert ex.loads_enabled
    mouse(ex, "button_press_event", ex.buoyancy_slider.ax, 0.2, 0.5)
    mouse(ex, "button_release_event", ex.buoyancy_slider.ax, 0.2, 0.5)
    assert ex.params == Parameters(2.0, -0.5, buoyancy=0.2)
    # a click on the map
    mouse(ex, "button_press_event", ex.ax, 0.5, 0.3)
    mouse(ex, "button_release_event", ex.ax, 0.5, 0.3)
    assert ex.point is not None and (ex.point.k, ex.point.mu) == (0.5, 0.3)
    assert echo.out[-1] == ex.info_text
    # Save
    monkeypatch.chdir(tmp_path)
    mouse(ex, "button_press_event", ex.save_ax, 0.5, 0.5)
    mouse(ex, "button_release_event", ex.save_ax, 0.5, 0.5)
    assert echo.out[-1] == "regime-g2-kp-0.5-b0.2.png" and Path(echo.out[-1]).is_file()


def test_a_refused_slider_value_is_shown_not_raised(explorer: Explorer) -> None:
    p = Parameters(3.0, 0.4, crest=1.0)
    assert explorer.params == p
    explorer.loads_check.set_active(0)  # loads on, then a buoyancy the block cannot carry
    explorer.buoyancy_slider.set_val(0.999)
    assert "not shown" not in explorer.info_text  # 0.999 is still < 1: accepted
    explorer._on_buoyancy(1.5)  # noqa: SLF001 - what a slider beyond its range would send
    assert explorer.info_text.startswith("not shown: ") and "buoyancy" in explorer.info_text


# -- the command ---------------------------------------------------------------------------------


def test_cli_without_a_display_exits_1(run_cli) -> None:
    run = run_cli(["explore", "--gamma", "3", "--kprime", "0.4"], env={"DISPLAY": None})
    assert run.code == 1
    assert run.stdout == ""
    (line,) = run.stderr.splitlines()
    assert line.startswith("regimemap: error: regimemap explore needs a display")
    assert "'agg'" in line.lower() and "-o FILE" in line


@pytest.mark.slow
@pytest.mark.deep
def test_cli_output_saves_the_first_view(run_cli, tmp_path: Path) -> None:
    out = tmp_path / "start.png"
    args = ["--gamma", "0.7", "--kprime", "-0.018", "--buoyancy", "0.318", "--uplift-ratio", "0.524"]
    run = run_cli(["explore", *args, "-o", str(out)])
    assert run.code == 0, run.stderr
    assert run.stdout == f"{out}\n"
    assert out.read_bytes() == plot_bytes(run_cli, tmp_path, args, "goda.png")


def test_cli_output_refuses_a_bad_suffix(run_cli, tmp_path: Path) -> None:
    run = run_cli(["explore", "-o", str(tmp_path / "x.txt")])
    assert run.code == 2 and "unknown file suffix .txt" in run.stderr
    assert not (tmp_path / "x.txt").exists()


def test_cli_options_are_checked(run_cli) -> None:
    run = run_cli(["explore", "--gamma", "0"])
    assert run.code == 2 and "--gamma" in run.stderr
    run = run_cli(["explore", "--resolution", "1"])
    assert run.code == 2 and "--resolution" in run.stderr


def test_explore_is_a_command(run_cli) -> None:
    run = run_cli(["--help"])
    assert "explore" in run.stdout
    run = run_cli(["explore", "--help"])
    assert run.code == 0 and "-o, --output FILE" in run.stdout


def test_drag_title_reads_as_plots() -> None:
    from regimemap.maps.figures.explore.text import drag_title
    from regimemap.maps.figures.mapplot import default_title

    # the drag title's symbols are Unicode, read back as plot's mathtext
    tex_of = {"\u03b3": r"\gamma", "k\u2032": "k'", "\u03b2": r"\beta", "\u03bd": r"\nu",
              "e\u1d64": "e_u", "\u2212": "-"}
    for p in (Parameters(3.0, -0.3), Parameters(0.7, -0.018, buoyancy=0.318, uplift_ratio=0.524),
              Parameters(1.2, 0.5, uplift=0.1, uplift_ratio=0.4, uplift_arm=0.25)):
        plain, tex = drag_title(p).split("\n"), default_title(p).split("\n")
        assert plain[0] == tex[0]
        assert "$" not in plain[1]  # no mathtext: nothing to parse again at each frame
        line = plain[1]
        for uni, sym in tex_of.items():
            line = line.replace(uni, sym)
        assert line.replace(" = ", "=") == tex[1].replace("$", "").replace(" = ", "=")


@pytest.mark.deep
def test_off_screen_explorer_stays_out_of_pyplot() -> None:
    import matplotlib.pyplot as plt
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    before = plt.get_fignums()
    ex = Explorer(Parameters(3.0, 0.4), compute=map_for_view, classify=classify_point, window=False,
                  echo=None)
    assert type(ex.fig.canvas) is FigureCanvasAgg and ex.fig.canvas.manager is None
    assert plt.get_fignums() == before
    ex.set_kprime(-0.2)
    assert_same_map(ex, Parameters(3.0, -0.2))
    ex.close()


# -- explore --design: the caisson's design wave ---------------------------------------------------


def _goda(tmp_path: Path) -> Path:
    from regimemap.caisson.file import example_design_text

    p = tmp_path / "goda.toml"
    p.write_text(example_design_text(), encoding="utf-8")
    return p


@pytest.mark.slow
@pytest.mark.deep
def test_cli_design_starts_at_the_design_wave(run_cli, tmp_path: Path) -> None:
    """The first view is the caisson's loaded map with its design point: plot's bytes with the
    block and the point that `regimemap caisson --json` gives."""
    import json

    goda = _goda(tmp_path)
    out = tmp_path / "start.png"
    run = run_cli(["explore", "--design", str(goda), "-o", str(out)])
    assert run.code == 0, run.stderr
    assert run.stdout == f"{out}\n"
    c = json.loads(run_cli(["caisson", str(goda), "--json"]).stdout)
    args = ["--gamma", repr(c["gamma"]), "--kprime", repr(c["kprime"]), "--buoyancy", repr(c["buoyancy"]),
            "--uplift-ratio", repr(c["uplift_ratio"]), "--uplift-arm", repr(c["uplift_arm"]),
            "--gyration", repr(c["gyration"]), "--crest", repr(c["crest"]),
            "--point", f"{c['k']!r},{c['mu']!r}"]
    assert out.read_bytes() == plot_bytes(run_cli, tmp_path, args, "goda.png")


def test_design_point_is_marked_with_its_answer(echo: Echo, tmp_path: Path) -> None:
    from regimemap.caisson.file import read_design
    from regimemap.caisson.report import caisson_report
    from regimemap.maps.points import DesignPoint

    report = caisson_report(read_design(_goda(tmp_path)).analysis_inputs())
    params = report.map.parameters()
    ex = open_explorer(params, echo=echo, point=DesignPoint(report.k, report.mu))
    try:
        assert ex.params == params and ex.loads_enabled  # beta and nu on their sliders
        assert ex.point == DesignPoint(report.k, report.mu)  # not rounded as a click would be
        assert ex.result is not None and ex.result.mode == Mode(report.mode) == Mode.RE
        assert ex.info_text == ex.describe(ex.result) and echo.out == []
    finally:
        ex.close()


def test_cli_design_refuses_the_block_and_bad_files(run_cli, tmp_path: Path) -> None:
    goda = _goda(tmp_path)
    run = run_cli(["explore", "--design", str(goda), "--gamma", "2", "--buoyancy", "0.3",
                   "-o", str(tmp_path / "x.png")])
    assert run.code == 2 and "--gamma, --buoyancy and --design exclude each other" in run.stderr
    bad = tmp_path / "bad.toml"
    bad.write_text(goda.read_text(encoding="utf-8").replace("width = 15.0", "widht = 15.0"), encoding="utf-8")
    run = run_cli(["explore", "--design", str(bad), "-o", str(tmp_path / "x.png")])
    assert run.code == 2 and "'--design'" in run.stderr and "line 22: unknown key [caisson] widht" in run.stderr
    assert not (tmp_path / "x.png").exists()
