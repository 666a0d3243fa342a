"""Atlas of small multiples and the k' animation."""

from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from regimemap import Parameters
from regimemap.maps.designer_view import view_extent as auto_extent  # the default view of export and atlas
from regimemap.maps.figures.animation import MAX_FRAMES, write_animation
from regimemap.maps.figures.atlas import MAX_PANELS, atlas_figure, write_atlas
from regimemap.maps.run_atlas import run_atlas
from regimemap.maps.sweeps import (
    atlas_extents,
    parse_values,
    points_outside,
    shared_extent,
    sweep_extent,
    sweep_frames,
)
from regimemap.mechanics.validation import check_gamma, check_kprime

pytestmark = pytest.mark.render


def _panels(fig):
    return [ax for ax in fig.axes if (ax.get_gid() or "").startswith("panel-")]


def test_atlas_panels_titles_and_shared_axes():
    gammas, kprimes = [1.0, 3.0], [-0.6, 0.4, 0.9]
    fig = atlas_figure(run_atlas(gammas, kprimes, samples=101))
    panels = _panels(fig)
    assert len(panels) == 6
    titles = [ax.get_title(loc="left") for ax in panels]
    assert titles[0] == r"$\gamma = 1$, $k' = -0.6$"
    assert titles[5] == r"$\gamma = 3$, $k' = 0.9$"
    lims = {(ax.get_xlim(), ax.get_ylim()) for ax in panels}
    assert len(lims) == 1  # one view for the whole figure
    (xl, yl), = lims
    want = shared_extent([auto_extent(Parameters(g, kp)) for g in gammas for kp in kprimes])
    assert (xl[1], yl[1]) == want
    assert len(fig.legends) == 1
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert sum("slide-rock" in t for t in labels) == 3 and any("rest" in t for t in labels)
    # tick labels only on the outer panels
    assert panels[0].xaxis.get_tick_params()["labelbottom"] is False
    assert panels[4].yaxis.get_tick_params()["labelleft"] is False


def test_atlas_share_row_and_none():
    gammas, kprimes = [1.0, 3.0], [-0.2, 0.4]
    ext = atlas_extents(gammas, kprimes, "row")
    assert ext[0][0] == ext[0][1] and ext[1][0] == ext[1][1]
    own = atlas_extents(gammas, kprimes, "none")
    assert own[1][1] == auto_extent(Parameters(3.0, 0.4))
    fig = atlas_figure(run_atlas(gammas, kprimes, share="none", samples=101))
    panels = _panels(fig)
    assert (panels[3].get_xlim()[1], panels[3].get_ylim()[1]) == own[1][1]
    fixed = atlas_extents(gammas, kprimes, "all", k_max=2.0, mu_max=1.0)
    assert {e for row in fixed for e in row} == {(2.0, 1.0)}
    with pytest.raises(ValueError, match="share must be"):
        atlas_extents(gammas, kprimes, "both")


@pytest.mark.parametrize("suffix", ["png", "svg"])
@pytest.mark.deep
def test_write_atlas_file(tmp_path, suffix):
    path = tmp_path / f"atlas.{suffix}"
    write_atlas(path, run_atlas([1.0, 2.0], [-0.2, 0.4], samples=101), dpi=40)
    data = path.read_bytes()
    if suffix == "png":
        w, h = atlas_figure(run_atlas([1.0, 2.0], [-0.2, 0.4], samples=11)).get_size_inches()
        with Image.open(path) as im:
            assert im.format == "PNG"
            assert im.size == (int(w * 40), int(h * 40))  # matplotlib truncates
    else:
        text = data.decode()
        assert text.lstrip().startswith("<?xml") and "</svg>" in text
        # one axes group per panel
        assert sum(f'id="panel-{i}-{j}"' in text for i in range(2) for j in range(2)) == 4


def test_atlas_limits():
    with pytest.raises(ValueError, match="panels exceed"):
        run_atlas([1.0] * 7, [0.0] * 7)
    with pytest.raises(ValueError, match="at least one"):
        run_atlas([], [0.0])
    with pytest.raises(ValueError, match="gamma must be"):
        run_atlas([-1.0], [0.0])
    assert MAX_PANELS == 48 and MAX_FRAMES == 400


@pytest.mark.deep
def test_animation_frames_and_size(tmp_path):
    path = tmp_path / "sweep.gif"
    kps = parse_values("-0.8:0.8:5", "kprime", check_kprime)
    n, size = write_animation(path, sweep_frames(3.0, kps, samples=101), dpi=40, fps=5)
    assert n == 5 and size == (208, 180)  # 5.2 x 4.5 inches at 40 dpi
    with Image.open(path) as im:
        assert im.format == "GIF" and im.n_frames == 5 and im.size == (208, 180)
        assert im.info.get("duration") == 200
        frames = []
        for i in range(im.n_frames):
            im.seek(i)
            frames.append(np.asarray(im.convert("RGB")))
    # the map changes with k' (the first and last frames differ a lot)
    assert np.mean(frames[0] != frames[-1]) > 0.05
    assert [f.name for f in tmp_path.iterdir()] == ["sweep.gif"]


@pytest.mark.deep
def test_animation_fixed_axes(tmp_path, monkeypatch):
    """Every frame is drawn on the same view."""
    import regimemap.maps.figures.animation as animation

    seen = []
    real = animation.draw_map

    def spy(ax, data, style=None):
        seen.append((data.k_max, data.mu_max))
        return real(ax, data, style)

    monkeypatch.setattr(animation, "draw_map", spy)
    kps = [-0.9, -0.3, 0.0, 0.5]
    write_animation(tmp_path / "a.gif", sweep_frames(1.0, kps, samples=51), dpi=30)
    assert len(seen) == 4 and len(set(seen)) == 1
    assert seen[0] == sweep_extent(1.0, kps)


def test_animation_rejects_bad_input(tmp_path):
    # the view given: the frames are not computed, and the view of 401 frames costs 9 CPU s
    with pytest.raises(ValueError, match=f"{MAX_FRAMES + 1} frames exceed the limit of {MAX_FRAMES}"):
        write_animation(tmp_path / "a.gif", sweep_frames(1.0, [0.0] * (MAX_FRAMES + 1), k_max=2.0, mu_max=2.0))
    with pytest.raises(ValueError, match=r"\.gif"):
        write_animation(tmp_path / "a.png", sweep_frames(1.0, [0.0]))
    with pytest.raises(ValueError, match="fps"):
        write_animation(tmp_path / "a.gif", sweep_frames(1.0, [0.0]), fps=0.0)
    with pytest.raises(ValueError, match="gamma"):
        sweep_frames(-1.0, [0.0])
    assert list(tmp_path.iterdir()) == []


def test_parse_values():
    assert parse_values("-1:1:5", "kprime", check_kprime) == [-1.0, -0.5, 0.0, 0.5, 1.0]
    assert parse_values(" 1, 2 ,3", "gamma", check_gamma) == [1.0, 2.0, 3.0]
    assert parse_values("0.3:0.3:1", "kprime", check_kprime) == [0.3]
    assert parse_values("2", "gamma", check_gamma) == [2.0]
    for text, match in [
        ("", "empty"),
        ("1,,2", "empty item"),
        ("1,a", "'a' is not a number"),
        ("-1:1", "not start:stop:count"),
        ("-1:1:0", "count .* must be a whole number >= 1"),
        ("-1:1:x", "count"),
        ("-1:1:1", "1 value between two different ends"),
        ("-2:1:5", r"start of '-2:1:5': kprime must be a number in \[-1, 1\]"),
        ("-1:1:401", "exceed the limit of 400"),
        ("0,1.5", r"kprime must be a number in \[-1, 1\], got 1.5"),
    ]:
        with pytest.raises(ValueError, match=match):
            parse_values(text, "kprime", check_kprime)


def test_shared_extent_and_points_outside():
    exts = [(1.0, 1.0), (2.0, 1.0), (3.0, 2.0), (100.0, 50.0)]
    km, mm = shared_extent(exts)
    assert 3.0 <= km < 100.0 and 1.0 <= mm < 50.0  # an outlier does not set the view
    assert shared_extent([(1.3, 0.7)]) == (1.3, 0.7)
    ps = [Parameters(3.0, -0.95), Parameters(3.0, 0.4), Parameters(2.0, -1.0)]
    out = points_outside(ps, 2.0, 2.0)
    assert out == [ps[0]]  # A at k = 6.67; k' = -1 has no A


@pytest.mark.deep
def test_atlas_gives_own_views_where_sharing_would_cram():
    from regimemap.maps.sweeps import resolve_share

    gammas, kprimes = [1.0, 3.0], [-0.6, 0.0, 0.9]
    share, ext, crammed = resolve_share(gammas, kprimes, "all")
    assert share == "none" and (3.0, 0.0) in crammed
    fig = atlas_figure(run_atlas(gammas, kprimes, samples=101))
    assert "own view" in fig._suptitle.get_text() and "cram" in fig._suptitle.get_text()
    views = {(ax.get_xlim(), ax.get_ylim()) for ax in _panels(fig)}
    assert len(views) > 1
