"""``regimemap plot``, ``figure`` and ``figures`` through click's CliRunner."""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from click.testing import CliRunner

from regimemap.cli import cli

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.fixture
def runner():
    return CliRunner()


def _ok(result):
    assert result.exit_code == 0, (result.output, result.exception)
    return result


def _usage(result, *words):
    """A usage error: exit 2, and the message names what is wrong."""
    assert result.exit_code == 2, (result.exit_code, result.output)
    for w in words:
        assert w in result.output, (w, result.output)
    assert "Traceback" not in result.output


def _no_partial_files(folder: Path):
    assert not [p for p in folder.iterdir() if p.name.endswith(".part")]


# -- plot --------------------------------------------------------------------------------------


@pytest.mark.render
def test_plot_default_name(runner, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    res = _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4"]))
    assert (tmp_path / "regime-g3-kp0.4.png").read_bytes().startswith(PNG)
    assert "regime-g3-kp0.4.png" in res.output
    _ok(runner.invoke(cli, ["plot", "--gamma", "2.5", "--kprime", "-0.3", "--format", "svg"]))
    assert (tmp_path / "regime-g2.5-kp-0.3.svg").exists()
    _no_partial_files(tmp_path)


@pytest.mark.render
@pytest.mark.parametrize("name,check", [
    ("map.png", lambda b: b.startswith(PNG)),
    ("map.svg", lambda b: ET.fromstring(b).tag.endswith("svg")),
    ("map.pdf", lambda b: b.startswith(b"%PDF") and b"/Type3" not in b),
    ("MAP.SVG", lambda b: b.lstrip().startswith(b"<?xml")),
])
@pytest.mark.deep
def test_plot_format_from_suffix(runner, tmp_path, name, check):
    out = tmp_path / name
    _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "-o", str(out)]))
    assert check(out.read_bytes())


@pytest.mark.render
def test_plot_format_option(runner, tmp_path):
    _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "-0.3", "--format", "pdf",
                            "-o", str(tmp_path / "below")]))
    assert (tmp_path / "below.pdf").read_bytes().startswith(b"%PDF")
    _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--format", "svg",
                            "-o", str(tmp_path / "m.svg")]))


@pytest.mark.parametrize("args,words", [
    (["-o", "map.jpg"], [".png, .svg or .pdf", "-o"]),
    (["--format", "jpg"], ["png, svg, pdf", "--format"]),
    (["-o", "map.svg", "--format", "png"], ["--format", ".svg"]),
    (["--gamma", "-1"], ["--gamma", "gamma must be"]),
    (["--kprime", "2"], ["--kprime", "[-1, 1]"]),
    (["--resolution", "1"], ["--resolution", "[2, 5000]"]),
    (["--dpi", "0"], ["--dpi", "[20, 1200]"]),
    (["--k-max", "-2"], ["--k-max", "[1e-06, 1e+06]"]),
    (["--modes", "RE,XX"], ["--modes", "RE, SL, RO, SRO-, SRO+, SRO'-"]),
    (["--point", "0.4"], ["--point", "K,MU"]),
    (["--point", "-1,0.5"], ["--point", ">= 0"]),
])
def test_plot_usage_errors(runner, tmp_path, monkeypatch, args, words):
    base = {"--gamma": "3", "--kprime": "0.4"}
    argv = ["plot"]
    for key, val in base.items():
        if key not in args:
            argv += [key, val]
    argv += args
    monkeypatch.chdir(tmp_path)
    _usage(runner.invoke(cli, argv), *words)
    assert list(tmp_path.iterdir()) == []  # nothing written


def test_plot_missing_or_unwritable_folder(runner, tmp_path):
    _usage(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "-o",
                               str(tmp_path / "nope" / "m.png")]), "--output", "does not exist")
    # /proc refuses new files even for root (permission bits do not stop root)
    _usage(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "-o", "/proc/m.png"]),
           "--output", "not writable")


@pytest.mark.render
def test_plot_options(runner, tmp_path):
    out = tmp_path / "m.svg"
    _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "-o", str(out),
                            "--k-max", "2", "--mu-max", "1", "--resolution", "201",
                            "--title", "My caisson", "--no-curves", "--no-labels",
                            "--modes", "re,SL,sro-", "--point", "0.45,0.6:caisson-A",
                            "--point", "1.5,0.2"]))
    text = out.read_text()
    assert "<!-- My caisson -->" in text  # text is drawn as paths, its string kept as a comment
    ET.fromstring(text)
    _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "-0.3", "--raw", "--modes",
                            "RO", "-o", str(tmp_path / "raw.png"), "--dpi", "40"]))


@pytest.mark.render
def test_plot_points_file(runner, tmp_path):
    good = tmp_path / "pts.csv"
    good.write_text("k,mu,name,gamma,kprime\n0.45,0.6,A,3,0.4\n0.2,0.1,B,,\n0.3,0.3,C,2,0.4\n")
    res = _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--points",
                                  str(good), "-o", str(tmp_path / "m.png"), "--dpi", "40"]))
    assert "1 point(s) have another gamma or kprime" in res.output  # C (stderr is mixed in)
    bad = tmp_path / "bad.csv"
    bad.write_text("k,mu\n0.1,0.2\n0.3,abc\n")
    res = runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--points", str(bad),
                              "-o", str(tmp_path / "n.png")])
    _usage(res, "--points", "line 3", "column mu")
    assert not (tmp_path / "n.png").exists()
    _usage(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--points",
                               str(tmp_path / "missing.csv")]), "--points")


@pytest.mark.render
def test_plot_warns_about_points_outside_the_view(runner, tmp_path):
    res = _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--k-max", "1",
                                  "--point", "5,0.1:far", "-o", str(tmp_path / "m.png"),
                                  "--dpi", "40"]))
    assert "outside the view" in res.output and "far" in res.output


@pytest.mark.render
def test_show_ambiguity_when_available(runner, tmp_path):
    pytest.importorskip("regimemap.maps.figures.ambiguity")
    _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "-0.3", "--show-ambiguity",
                            "-o", str(tmp_path / "m.png"), "--dpi", "40"]))
    assert (tmp_path / "m.png").read_bytes().startswith(PNG)


@pytest.mark.render
def test_show_ambiguity_keeps_the_drawn_artists_current(runner, tmp_path, monkeypatch):
    """The overlay rebuilds the legend; the map's MapArtists then holds the new one."""
    import regimemap.maps.figures.figure as render

    seen = []
    original = render.map_figure

    def spy(*args, **kwargs):
        fig, ax, art = original(*args, **kwargs)
        seen.append((ax, art))
        return fig, ax, art

    monkeypatch.setattr(render, "map_figure", spy)
    _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "-0.2", "--k-max", "16",
                            "--mu-max", "3", "--show-ambiguity", "-o", str(tmp_path / "m.svg")]))
    (ax, art), = seen
    assert art.legend is ax.get_legend()
    assert "several modes admissible" in [t.get_text() for t in art.legend.get_texts()]


# -- figure / figures ----------------------------------------------------------------------------


@pytest.mark.render
@pytest.mark.deep
def test_figure_default_name_and_formats(runner, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    _ok(runner.invoke(cli, ["figure", "3.9a"]))
    assert (tmp_path / "fig-3.9a.png").read_bytes().startswith(PNG)
    _ok(runner.invoke(cli, ["figure", "4.7b", "--format", "svg"]))
    assert (tmp_path / "fig-4.7b.svg").exists()
    _ok(runner.invoke(cli, ["figure", "Fig. 3.10", "-o", "x.pdf"]))
    assert (tmp_path / "x.pdf").read_bytes().startswith(b"%PDF")


def test_figure_unknown_id_suggests(runner):
    res = runner.invoke(cli, ["figure", "3.9"])
    _usage(res, "FIGURE_ID", "3.9a", "3.9b")
    res = runner.invoke(cli, ["figure", "4.8a"])
    _usage(res, "FIGURE_ID", "Did you mean")


@pytest.mark.render
@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_figures_all(runner, tmp_path):
    res = _ok(runner.invoke(cli, ["figures", "--out", str(tmp_path), "--format", "svg,png",
                                  "--dpi", "30"]))
    names = sorted(p.name for p in tmp_path.iterdir())
    assert len(names) == 50
    assert "fig-2.1.svg" in names and "fig-3.9a.svg" in names and "fig-4.7b.png" in names
    # one line per written file on standard output: its path
    assert sorted(Path(line).name for line in res.output.splitlines()) == names
    # the same bytes as one figure drawn alone
    _ok(runner.invoke(cli, ["figure", "3.10", "-o", str(tmp_path / "alone.svg")]))
    assert (tmp_path / "alone.svg").read_bytes() == (tmp_path / "fig-3.10.svg").read_bytes()


def test_figures_errors_and_list(runner, tmp_path):
    _usage(runner.invoke(cli, ["figures", "--out", str(tmp_path / "none" / "deeper")]), "--out",
           "does not exist")
    _usage(runner.invoke(cli, ["figures", "--out", str(tmp_path), "--format", "png,gif"]),
           "--format", "png, svg, pdf")
    res = _ok(runner.invoke(cli, ["figures", "--list"]))
    lines = [ln for ln in res.output.splitlines() if ln.strip()]
    assert len(lines) == 25 and lines[0].startswith("2.1 ") and lines[1].startswith("3.1 ")


# -- help, version, import cost ------------------------------------------------------------------


@pytest.mark.parametrize("cmd", [[], ["plot"], ["figure"], ["figures"]])
def test_help(runner, cmd):
    for flag in ("--help", "-h"):
        res = _ok(runner.invoke(cli, cmd + [flag]))
        assert "Usage:" in res.output
        assert "Examples:" in res.output


def test_help_lists_the_options(runner):
    out = _ok(runner.invoke(cli, ["plot", "--help"])).output
    for opt in ("--gamma", "--kprime", "--output", "--format", "--k-max", "--mu-max",
                "--resolution", "--dpi", "--title", "--no-curves", "--no-labels", "--modes",
                "--point", "--points", "--show-ambiguity", "regime-g3-kp0.4"):
        assert opt in out, opt


def test_version(runner):
    res = _ok(runner.invoke(cli, ["--version"]))
    assert "regimemap" in res.output


@pytest.mark.subprocess
def test_help_does_not_import_matplotlib():
    code = (
        "import sys\n"
        "from regimemap.cli import main\n"
        "try:\n"
        "    main(['--help'])\n"
        "except SystemExit:\n"
        "    pass\n"
        "for cmd in (['plot', '--help'], ['figures', '--help']):\n"
        "    try:\n"
        "        main(cmd)\n"
        "    except SystemExit:\n"
        "        pass\n"
        "print('MPL', [m for m in sys.modules if m.split('.')[0] == 'matplotlib'][:3], "
        "file=sys.stderr)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert "MPL []" in out.stderr, out.stderr


@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_main_entry_point_exit_codes(tmp_path):
    """main() in one process: exit 0 and nothing on stderr for each format, then the process
    itself ends with main()'s exit 2 and one line for a suffix it cannot write."""
    code = (
        "import contextlib, io, sys\n"
        "from regimemap.cli import main\n"
        f"def plot(name): return ['plot', '--gamma', '3', '--kprime', '0.4', '-o', {str(tmp_path)!r} + '/' + name]\n"
        "for name in ('m.svg', 'm.pdf', 'm.png'):\n"
        "    err = io.StringIO()\n"
        "    try:\n"
        "        with contextlib.redirect_stderr(err):\n"
        "            main(plot(name))\n"
        "    except SystemExit as e:\n"
        "        print(name, e.code, repr(err.getvalue()))\n"
        "main(plot('m.gif'))\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    # each run prints the path it wrote, returns 0 and writes nothing on stderr
    assert run.stdout.splitlines() == [line for name in ("m.svg", "m.pdf", "m.png")
                                       for line in (str(tmp_path / name), f"{name} 0 ''")], run
    assert sorted(p.name for p in tmp_path.iterdir()) == ["m.pdf", "m.png", "m.svg"]
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert run.stderr.count("\n") == 1 and ".png, .svg or .pdf" in run.stderr, run.stderr


# -- start-up: the cyclic GC is paused while matplotlib is imported --------------------------


def test_gc_paused_until_matplotlib_is_imported_then_restored():
    import gc

    from regimemap.cli._main import gc_paused_at_start, import_matplotlib

    assert gc.isenabled()
    frozen_before = gc.get_freeze_count()
    with gc_paused_at_start():
        assert not gc.isenabled()  # the heavy imports run without collections
        import_matplotlib()
        assert gc.isenabled()  # ... then drawing collects again
        assert gc.get_freeze_count() > frozen_before  # what the imports made is frozen
        import_matplotlib()  # a second call changes nothing
        assert gc.isenabled()
    assert gc.isenabled() and gc.get_freeze_count() == frozen_before


def test_gc_does_not_thaw_what_the_caller_froze():
    import gc

    from regimemap.cli._main import gc_paused_at_start, import_matplotlib

    caller_owned = [[]]  # a tracked object the caller froze: it must stay out of the collected generations
    gc.freeze()
    try:
        with gc_paused_at_start():
            import_matplotlib()
            assert gc.isenabled()
        # the freeze count itself may fall (frozen objects freed by reference counting), so ask
        # whether the caller's object is still frozen: gc.get_objects() lists only the generations
        assert gc.isenabled() and not any(o is caller_owned for o in gc.get_objects())
    finally:
        gc.unfreeze()
    assert any(o is caller_owned for o in gc.get_objects())


def test_gc_left_disabled_when_the_caller_disabled_it():
    import gc

    from regimemap.cli._main import gc_paused_at_start, import_matplotlib

    gc.disable()
    try:
        with gc_paused_at_start():
            import_matplotlib()
            assert not gc.isenabled()
        assert not gc.isenabled() and gc.get_freeze_count() == 0
    finally:
        gc.enable()


@pytest.mark.render
@pytest.mark.parametrize("args", [["--version"], ["plot", "--gamma", "0", "--kprime", "0"],
                                  ["plot", "--gamma", "3", "--kprime", "0.4", "-o", "{tmp}/m.svg"],
                                  ["figure", "3.9a", "-o", "{tmp}/f.png"]])
def test_main_restores_the_gc(tmp_path, capsys, args):
    import gc

    from regimemap.cli import main

    with pytest.raises(SystemExit):
        main([a.format(tmp=tmp_path) for a in args])
    assert gc.isenabled() and gc.get_freeze_count() == 0


@pytest.mark.subprocess
def test_drawing_commands_import_matplotlib_with_the_gc_paused(tmp_path):
    """In the console script no collection runs while matplotlib is imported; drawing collects."""
    code = (
        "import gc, sys\n"
        "n = [0]\n"
        "gc.callbacks.append(lambda phase, info: phase == 'start' and n.__setitem__(0, n[0] + 1))\n"
        "import regimemap.cli.plot as plot\n"
        "original, seen = plot.import_matplotlib, {}\n"
        "def probe():\n"
        "    seen['mpl_before'] = 'matplotlib' in sys.modules\n"
        "    seen['before'] = n[0]\n"
        "    original()\n"
        "    seen['after'] = n[0]\n"
        "plot.import_matplotlib = probe\n"
        "from regimemap.cli import main\n"
        "try:\n"
        f"    main(['plot', '--gamma', '3', '--kprime', '0.4', '-o', {str(tmp_path / 'm.png')!r}])\n"
        "except SystemExit as e:\n"
        "    assert e.code == 0, e.code\n"
        "print(seen['mpl_before'], seen['after'] - seen['before'], n[0] - seen['after'],\n"
        "      gc.isenabled(), file=sys.stderr)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    mpl_before, during, after, enabled = out.stderr.split()
    assert mpl_before == "False"  # matplotlib really is imported in there ...
    assert during == "0"  # ... without a collection
    assert int(after) > 0 and enabled == "True"  # drawing collects again


@pytest.mark.subprocess
def test_console_script_skips_the_final_collections(tmp_path):
    """console_main freezes the heap before the interpreter exits (atexit still runs)."""
    code = (
        "import atexit, gc, sys\n"
        "atexit.register(lambda: print('FROZEN', gc.get_freeze_count() > 0, file=sys.stderr))\n"
        f"sys.argv = ['regimemap', 'plot', '--gamma', '3', '--kprime', '0.4', '-o', "
        f"{str(tmp_path / 'm.png')!r}]\n"
        "from regimemap.cli import console_main\n"
        "console_main()\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert "FROZEN True" in out.stderr
    assert out.stdout.strip() == str(tmp_path / "m.png")  # stdout flushed at exit
    assert (tmp_path / "m.png").read_bytes().startswith(PNG)


@pytest.mark.subprocess
def test_python_dash_m_regimemap(tmp_path):
    ok = subprocess.run([sys.executable, "-m", "regimemap", "--version"], capture_output=True,
                        text=True)
    assert ok.returncode == 0 and "regimemap" in ok.stdout
    bad = subprocess.run([sys.executable, "-m", "regimemap", "plot", "--gamma", "-1",
                          "--kprime", "0"], capture_output=True, text=True, cwd=tmp_path)
    assert bad.returncode == 2 and "Traceback" not in bad.stderr and "--gamma" in bad.stderr
    assert list(tmp_path.iterdir()) == []


# -- --modes: every mode the map can show (issue 20, item 8) ---------------------------------------

#: A loaded block whose map shows rock about O' (uplift near O) and lift-off further right.
_RO_PRIME = ["--gamma", "0.5", "--kprime", "-0.5", "--uplift-ratio", "4", "--uplift-arm", "-1"]


@pytest.mark.render
def test_plot_modes_of_a_loaded_map(runner, tmp_path):
    out = tmp_path / "m.svg"
    _ok(runner.invoke(cli, ["plot", *_RO_PRIME, "--modes", "RO',lo", "-o", str(out)]))
    text = out.read_text()
    assert "<!-- rock about O' -->" in text  # the key names the mode shaded
    assert "<!-- Modes $RO'$, $LO$, block with loads -->" in text
    _ok(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--uplift-ratio", "1",
                            "--modes", "LO", "--raw", "-o", str(tmp_path / "lo.png"), "--dpi", "40"]))


def test_plot_modes_the_map_cannot_show(runner, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    # RO' and LO need loads: the message names the modes this map can show
    r = runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--modes", "RE,LO"])
    _usage(r, "'--modes'", "mode LO appears only on the map of a loaded block",
           "this map's modes: RE, SL, RO, SRO-, SRO+, SRO'-")
    _usage(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--crest", "1.5",
                               "--modes", "RO'"]), "'--modes'", "mode RO' appears only")
    # SRO'+ is on no map; an unknown label lists all
    _usage(runner.invoke(cli, ["plot", "--gamma", "3", "--kprime", "0.4", "--uplift-ratio", "1",
                               "--modes", "SRO'+"]), "'--modes'", "never appears on a map",
           "RE, SL, RO, SRO-, SRO+, SRO'- (and RO', LO on the map of a loaded block)")
    assert list(tmp_path.iterdir()) == []  # nothing written
