"""``regimemap atlas`` and ``regimemap animate`` through click's CliRunner."""

from __future__ import annotations

import pytest
from click.testing import CliRunner
from PIL import Image

from regimemap.cli import atlas as cli_atlas
from regimemap.cli import cli
from regimemap.maps.figures import atlas as atlas_mod


def run(*args: str):
    return CliRunner().invoke(cli, list(args))


@pytest.mark.parametrize("cmd,example", [
    ("atlas", "regimemap atlas --gamma 1,2,3 --kprime -0.6,-0.2,0,0.4,0.9 -o atlas.svg"),
    ("animate", "regimemap animate --gamma 3 --kprime -1:1:41 -o sweep.gif"),
])
@pytest.mark.parametrize("flag", ["-h", "--help"])
def test_help(cmd, example, flag):
    r = run(cmd, flag)
    assert r.exit_code == 0
    assert "Examples:" in r.output and example in r.output


def test_limits_match_library():
    from regimemap.maps.figures import animation

    assert cli_atlas.MAX_PANELS == atlas_mod.MAX_PANELS
    assert cli_atlas.MAX_FRAMES == animation.MAX_FRAMES


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_atlas_svg_has_every_panel(tmp_path):
    out = tmp_path / "atlas.svg"
    r = run("atlas", "--gamma", "1,3", "--kprime", "-0.6,0,0.9", "-o", str(out))
    assert r.exit_code == 0, r.output
    text = out.read_text()
    ids = [f'id="panel-{i}-{j}"' for i in range(2) for j in range(3)]
    assert all(i in text for i in ids)
    assert 'id="panel-2-0"' not in text and 'id="panel-0-3"' not in text


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_atlas_says_when_it_does_not_share(tmp_path):
    r = run("atlas", "--gamma", "1,2,3", "--kprime", "-0.6,-0.2,0,0.4,0.9", "--dpi", "30",
            "-o", str(tmp_path / "a.png"))
    assert r.exit_code == 0, r.output
    assert "each panel has its own view" in r.output
    assert "(gamma, k') = (1, 0.9), " in r.output and "more into a corner" in r.output


@pytest.mark.render
def test_atlas_png_range_syntax(tmp_path):
    out = tmp_path / "a.png"
    r = run("atlas", "--gamma", "2", "--kprime", "-1:1:3", "--share", "none", "--dpi", "40",
            "-o", str(out))
    assert r.exit_code == 0, r.output
    with Image.open(out) as im:
        assert im.format == "PNG" and im.size[0] > im.size[1]


@pytest.mark.render
def test_atlas_notes_panels_whose_point_a_is_cut(tmp_path):
    r = run("atlas", "--gamma", "3", "--kprime", "-0.95,0,0.2,0.4", "--dpi", "30",
            "--view", "report", "--k-max", "2", "--mu-max", "2", "-o", str(tmp_path / "a.png"))
    assert r.exit_code == 0, r.output
    assert "point A lies outside the shared view for gamma = 3, k' = -0.95" in r.output


@pytest.mark.parametrize("args,param,text", [
    (("--gamma", "1,x", "--kprime", "0"), "--gamma", "'x' is not a number"),
    (("--gamma", "-1", "--kprime", "0"), "--gamma", "gamma must be"),
    (("--gamma", "1", "--kprime", "0,2"), "--kprime", "[-1, 1]"),
    (("--gamma", "1", "--kprime", "-1:1"), "--kprime", "start:stop:count"),
    (("--gamma", "1:3:10", "--kprime", "-1:1:10"), "panels", "limit of 48"),
    (("--gamma", "1", "--kprime", "0", "--share", "both"), "--share", "both"),
    (("--kprime", "0",), "--gamma", ""),
])
def test_atlas_bad_input(tmp_path, args, param, text):
    out = tmp_path / "a.png"
    r = run("atlas", *args, "-o", str(out))
    assert r.exit_code == 2, r.output
    assert param in r.output and text in r.output
    assert not out.exists()


def test_atlas_bad_output(tmp_path):
    r = run("atlas", "--gamma", "1", "--kprime", "0", "-o", str(tmp_path / "a.txt"))
    assert r.exit_code == 2 and "--output" in r.output and ".png, .svg or .pdf" in r.output


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_animate(tmp_path):
    out = tmp_path / "sweep.gif"
    r = run("animate", "--gamma", "3", "--kprime", "-1:1:6", "--dpi", "30", "--fps", "4",
            "-o", str(out))
    assert r.exit_code == 0, r.output
    assert r.stdout.strip() == str(out)
    assert "6 frames, 156 x 135 pixels" in r.stderr
    with Image.open(out) as im:
        assert im.n_frames == 6 and im.size == (156, 135)
        assert im.info["duration"] == 250


@pytest.mark.parametrize("args,param,text", [
    (("--gamma", "3", "--kprime", "-1:1:401"), "--kprime", "limit of 400"),
    (("--gamma", "3", "--kprime", "-1:1:0"), "--kprime", ">= 1"),
    (("--gamma", "3", "--kprime", "-1.5:1:5"), "--kprime", "[-1, 1]"),
    (("--gamma", "0", "--kprime", "0"), "--gamma", ""),
    (("--gamma", "3", "--kprime", "0", "--fps", "0"), "--fps", ""),
    (("--gamma", "3", "--kprime", "0", "--dpi", "5"), "--dpi", ""),
])
def test_animate_bad_input(tmp_path, args, param, text):
    r = run("animate", *args, "-o", str(tmp_path / "s.gif"))
    assert r.exit_code == 2, r.output
    assert param in r.output and text in r.output
    assert list(tmp_path.iterdir()) == []


def test_animate_needs_gif(tmp_path):
    r = run("animate", "--gamma", "3", "--kprime", "0:1:2", "-o", str(tmp_path / "x.png"))
    assert r.exit_code == 2
    assert "--output" in r.output and ".gif" in r.output
    assert list(tmp_path.iterdir()) == []


# -- k' up to the crest (issue 20, item 8): the rule of `regimemap plot` ---------------------------

@pytest.mark.parametrize("cmd,args,text", [
    ("atlas", ("--gamma", "1", "--kprime", "1.2"), "kprime must be a number in [-1, 1], got 1.2"),
    ("atlas", ("--gamma", "1", "--kprime", "1.2", "--crest", "1.1"), "[-1, 1.1], got 1.2"),
    ("atlas", ("--gamma", "1", "--kprime", "1.2", "--crest", "1.1,1.5"), "[-1, 1.1], got 1.2"),
    ("atlas", ("--gamma", "1", "--kprime", "2000"), "[-1, 1] (up to --crest), got 2000"),
    ("animate", ("--gamma", "3", "--kprime", "0.5:1.5:3"), "[-1, 1], got 1.5"),
    ("animate", ("--gamma", "3", "--kprime", "0.5:1.5:3", "--crest", "1.2"), "[-1, 1.2], got 1.5"),
])
def test_kprime_above_its_crest_is_a_usage_error(tmp_path, cmd, args, text):
    out = tmp_path / ("a.png" if cmd == "atlas" else "a.gif")
    r = run(cmd, *args, "-o", str(out))
    assert r.exit_code == 2, r.output
    assert "'--kprime'" in r.output and text in r.output and "Traceback" not in r.output
    assert not out.exists()


@pytest.mark.render
@pytest.mark.deep
def test_atlas_and_animate_take_kprime_up_to_the_crest(tmp_path):
    out = tmp_path / "a.png"
    r = run("atlas", "--gamma", "1,3", "--kprime", "0.4,1.2,1.5", "--crest", "1.5", "--dpi", "30",
            "-o", str(out))
    assert r.exit_code == 0, r.output
    assert out.read_bytes()[:4] == b"\x89PNG"
    gif = tmp_path / "a.gif"
    r = run("animate", "--gamma", "3", "--kprime", "1:1.5:3", "--crest", "1.5", "--dpi", "30", "-o", str(gif))
    assert r.exit_code == 0, r.output
    with Image.open(gif) as im:
        assert im.n_frames == 3


def test_the_library_takes_kprime_up_to_the_crest():
    from regimemap.maps.sweeps import checked_values

    assert checked_values([3], [0.5, 1.5], "kprime", {"crest": 1.5}) == ([3.0], [0.5, 1.5])
    with pytest.raises(ValueError, match=r"kprime must be a number in \[-1, 1\], got 1.5"):
        checked_values([3], [1.5])
    with pytest.raises(ValueError, match=r"\[-1, 1.2\]"):
        checked_values([3], [1.5], fixed={"crest": 1.2})
