"""run_atlas and run_animation: every panel's (frame's) block, view and map, and the notes."""

from __future__ import annotations

import pytest

from regimemap.drawing.limits import MAX_PANELS as CLI_MAX_PANELS
from regimemap.maps.mapdata import compute_map
from regimemap.maps.sweeps import MAX_PANELS, resolve_share
from regimemap.workflows import AnimationRecord, AtlasRecord, run_animation, run_atlas


def test_the_panels_maps_are_computed_in_their_views():
    gammas, values = [1.0, 3.0], [-0.6, 0.4]
    rec = run_atlas(gammas, values, samples=31)
    assert isinstance(rec, AtlasRecord)
    share, ext, crammed = resolve_share(gammas, values, "all")
    assert rec.share == share and [list(r) for r in rec.extents] == ext and list(rec.crammed) == crammed
    for i, row in enumerate(rec.maps):
        for j, data in enumerate(row):
            assert (data.k_max, data.mu_max) == ext[i][j]
            assert data.params == rec.blocks[i][j]
    one = compute_map(rec.blocks[0][1], k_max=ext[0][1][0], mu_max=ext[0][1][1], samples=31)
    assert rec.maps[0][1].polygons.keys() == one.polygons.keys()


@pytest.mark.slow
def test_crammed_panels_get_their_own_views_and_a_note():
    rec = run_atlas([1.0, 2.0, 3.0], [-0.6, 0.0, 0.4], samples=21)
    assert rec.share == "none" and rec.crammed
    (n,) = rec.notices
    assert n.code == "crammed" and "(gamma, k') = (2, 0), (3, 0)" in n.message


def test_point_a_outside_the_shared_report_view_is_noted():
    rec = run_atlas([1.0, 3.0], [-0.9, 0.4], view="report", k_max=1.0, mu_max=1.0, samples=21)
    (n,) = rec.notices
    assert n.code == "outside-view" and n.value == 2
    assert n.message.startswith("point A lies outside the shared view for gamma = 1, k' = -0.9")


def test_a_swept_load_and_its_fixed_rest():
    rec = run_atlas([0.7], [0.0, 0.5], sweep="uplift_ratio", fixed={"kprime": -0.018}, samples=21)
    assert rec.loaded and [p.uplift_ratio for p in rec.blocks[0]] == [0.0, 0.5]
    assert all(p.kprime == -0.018 for p in rec.blocks[0])


def test_limits():
    assert MAX_PANELS == CLI_MAX_PANELS == 48
    with pytest.raises(ValueError, match="panels exceed"):
        run_atlas([1.0] * 7, [0.0] * 7)
    with pytest.raises(ValueError, match="at least one"):
        run_atlas([], [0.0])
    with pytest.raises(ValueError, match="gamma must be"):
        run_atlas([-1.0], [0.0])


def test_animation_frames_and_their_note():
    rec = run_animation(3.0, [-0.9, 0.0, 0.9], view="report", k_max=0.5, mu_max=0.5, samples=21)
    assert isinstance(rec, AnimationRecord)
    assert rec.frames.values == (-0.9, 0.0, 0.9) and (rec.frames.k_max, rec.frames.mu_max) == (0.5, 0.5)
    (n,) = rec.notices
    assert n.code == "outside-view" and "k' = -0.9" in n.message
    assert run_animation(3.0, [-0.9, 0.9], samples=21).notices == ()
