"""``regimemap simulate``, ``regimemap outcome`` and ``regimemap dynamics-figures`` through run_main."""

from __future__ import annotations

import csv
import errno
import json
import re
from pathlib import Path

import numpy as np
import pytest

from regimemap.dynamics import Block, Pulse, simulate

from ..conftest import invoke_cli

MR = ["--gamma", "3", "--half-width", "0.2", "--kprime", "0", "--mu", "5"]
HALF_SINE = ["--pulse", "half-sine", "--k-peak", "0.5", "--duration", "0.5"]


def run(*args: str):
    return invoke_cli(list(args))


def one_error(r, code: int, pattern: str) -> str:
    assert "Traceback" not in r.output, r.output
    assert r.code == code, (r.code, r.output)
    lines = r.error_lines()
    assert len(lines) == 1, r.stderr
    assert re.search(pattern, lines[0]), lines[0]
    return lines[0]


# -- simulate: output ------------------------------------------------------------------------------

@pytest.mark.slow
def test_simulate_text_names_phases_and_outcome():
    r = run("simulate", *MR, *HALF_SINE)
    assert r.code == 0, r.output
    out = r.stdout
    for piece in ("phases", "RE      rest", "RO      rock about O", "RO'     rock about O'",
                  "rock only: not overturned", "max rotation", "deg)", "residual rotation",
                  "residual slide", "positive towards O", "impacts", "initial mode        RE (rest)"):
        assert piece in out, (piece, out)
    # the phases with their start times: the first rocking phase starts when k reaches tan(alpha)
    m = re.search(r"^\s+([0-9.]+)\s+RO\s+rock about O$", out, re.M)
    assert m is not None
    t_uplift = np.arcsin((1 / 3) / 0.5) / (2 * np.pi)  # k(t) = 0.5 sin(2 pi t) = tan(alpha)
    assert float(m.group(1)) == pytest.approx(t_uplift, abs=2e-3)


@pytest.mark.slow
def test_simulate_json_keys_rounding_and_agreement_with_the_library():
    r = run("simulate", *MR, "--pulse", "half-sine", "--k-peak", "0.6", "--duration", "0.5", "--json")
    assert r.code == 0, r.output
    d = json.loads(r.stdout)
    for key in ("overturned", "max_rotation", "residual_rotation", "residual_slide", "impacts", "phases",
                "initial_mode", "inputs", "category", "settled", "end_time"):
        assert key in d
    assert d["overturned"] is True and d["category"] == "overturned"
    assert d["phases"][0] == {"mode": "RE", "start": 0.0}
    assert all(set(p) == {"mode", "start"} for p in d["phases"])
    assert d["inputs"]["gamma"] == 3.0 and d["inputs"]["pulse"] == "half-sine"
    assert d["inputs"]["k_peak"] == 0.6 and d["inputs"]["restitution"] is None
    sim = simulate(Block(B=0.2, gamma=3.0, mu=5.0), Pulse.half_sine(0.6, 0.5))
    assert d["max_rotation"] == float(f"{sim.max_rotation[0]:.12g}")
    assert d["impacts"] == int(sim.impacts[0])

    def digits(x: float) -> int:
        return len(repr(x).split("e")[0].replace("-", "").replace(".", "").lstrip("0"))

    assert all(digits(v) <= 12 for v in (d["max_rotation"], d["end_time"], d["max_rotation_deg"]))
    assert d["files"] == []


@pytest.mark.slow
@pytest.mark.deep
def test_simulate_history_csv_and_npz(tmp_path):
    csv_path, npz_path = tmp_path / "h.csv", tmp_path / "h.npz"
    r = run("simulate", *MR, *HALF_SINE, "-o", str(csv_path))
    assert r.code == 0, r.output
    assert r.stdout.splitlines()[-1] == str(csv_path)
    rows = list(csv.DictReader(csv_path.open()))
    assert list(rows[0]) == ["t", "k", "x", "y", "theta", "vx", "vy", "omega", "slide", "phase"]
    assert rows[0]["phase"] == "" and {r_["phase"] for r_ in rows[1:]} >= {"RE", "RO", "RO'"}
    r = run("simulate", *MR, *HALF_SINE, "-o", str(npz_path), "--json")
    assert r.code == 0, r.output
    assert json.loads(r.stdout)["files"] == [str(npz_path)]
    with np.load(npz_path) as z:
        assert z["t"].shape == z["theta"].shape == (len(rows),)
        np.testing.assert_array_equal(z["theta"], [float(r_["theta"]) for r_ in rows])
        assert float(z["gamma"]) == 3.0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["h.csv", "h.npz"]


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_simulate_plot_and_animation(tmp_path):
    png, gif = tmp_path / "run.png", tmp_path / "run.gif"
    r = run("simulate", *MR, "--mu", "0.35", "--pulse", "half-sine", "--k-peak", "0.6", "--duration", "0.5",
            "--plot", str(png), "--animate", str(gif))
    assert r.code == 0, r.output
    assert png.read_bytes().startswith(b"\x89PNG") and gif.read_bytes().startswith(b"GIF8")
    assert r.stdout.splitlines()[-2:] == [str(png), str(gif)]
    assert "frames" in r.stderr
    from PIL import Image

    with Image.open(gif) as im:
        assert im.n_frames >= 60


@pytest.mark.slow
@pytest.mark.deep
def test_simulate_pulse_file(tmp_path):
    f = tmp_path / "record.csv"
    t = np.linspace(0, 0.5, 51)
    f.write_text("t,k,kprime\n" + "".join(f"{float(a)!r},{float(0.5 * np.sin(2 * np.pi * a))!r},0\n" for a in t))
    args = ["--gamma", "3", "--half-width", "0.2", "--mu", "5"]
    r = run("simulate", *args, "--pulse-file", str(f), "--json")
    assert r.code == 0, r.output
    d = json.loads(r.stdout)
    ref = json.loads(run("simulate", *MR, *HALF_SINE, "--json").stdout)
    assert d["category"] == ref["category"] == "rock only"
    assert d["max_rotation"] == pytest.approx(ref["max_rotation"], rel=0.02)
    one_error(run("simulate", *args, "--kprime", "0", "--pulse-file", str(f)), 2,
              r"--kprime and the kprime column .* exclude each other")
    one_error(run("simulate", *args, "--pulse-file", str(f), "--k-peak", "1"), 2,
              r"--k-peak and --pulse-file exclude each other")


# -- simulate: usage errors exit 2, name the option and the range, write nothing ---------------------

@pytest.mark.parametrize("args,pattern", [
    (["--half-width", "-1"], r"'--half-width'.*half_width must be a finite number in \[0\.001, 1000\], got '-1'"),
    (["--half-width", "1e-300"], r"'--half-width'.*\[0\.001, 1000\], got '1e-300'"),
    (["--mu", "nan"], r"'--mu'.*mu must be a finite number in \[0, 100\]"),
    (["--duration", "0"], r"'--duration'.*duration must be a finite number in \[0\.0001, 100\]"),
    (["--k-peak", "x"], r"'--k-peak'.*not a number"),
    (["--restitution", "2"], r"'--restitution'.*\[0, 1\]"),
    (["--buoyancy", "1"], r"'--buoyancy'.*\[0, 1\)"),
    (["--buoyancy", "0.5", "--uplift", "0.6"], r"'--uplift' / '--buoyancy'.*buoyancy \+ uplift must be < 1"),
    (["--gyration", "5"], r"'--gyration'.*\[0\.001, 3\.16228\] for gamma = 3"),
    (["--gyration", "1e-300"], r"'--gyration'.*\[0\.001, 1000\], got '1e-300'"),
    (["--uplift-arm", "1.5"], r"'--uplift-arm'.*\[-1, 1\]"),
    (["--gamma", "0"], r"'--gamma'.*\[0\.001, 1000\]"),
    (["--kprime", "2"], r"'--kprime'.*\[-1, 1\]"),
    (["--pulse", "square"], r"'--pulse'.*'square' is not one of"),
    (["-o", "{tmp}/h.txt"], r"'--output'.*unknown file suffix \.txt.*use \.npz or \.csv for the time history"),
    (["--plot", "{tmp}/h.gif"], r"'--plot'.*\.png, \.svg or \.pdf"),
    (["--animate", "{tmp}/h.png"], r"'--animate'.*\.gif"),
    (["-o", "{tmp}/missing/h.csv"], r"'--output'.*does not exist"),
    (["--duration", "100", "--half-width", "0.01"], r"'--duration'.*time steps.*more than the limit"),
])
def test_simulate_usage_errors(tmp_path, args, pattern):
    base = dict(zip(MR[::2], MR[1::2]))
    base.update(dict(zip(HALF_SINE[::2], HALF_SINE[1::2])))
    extra = [a.replace("{tmp}", str(tmp_path)) for a in args]
    for k, v in zip(extra[::2], extra[1::2]):
        base[k] = v
    argv = [x for kv in base.items() for x in kv]
    one_error(run("simulate", *argv), 2, pattern)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("drop,pattern", [
    ("--pulse", r"missing option\(s\) --pulse"),
    ("--duration", r"missing option\(s\) --duration"),
    ("--kprime", r"missing option --kprime"),
])
def test_simulate_missing_options(drop, pattern):
    args = MR + HALF_SINE
    i = args.index(drop)
    one_error(run("simulate", *(args[:i] + args[i + 2:])), 2, pattern)


# -- the pulse file ----------------------------------------------------------------------------------

@pytest.mark.parametrize("text,pattern", [
    ("time,k\n0,0\n1,1\n", r"p\.csv, line 1: missing column\(s\) t; the header must name t and k"),
    ("t,k\n0,0\n0.1,lots\n", r"p\.csv, line 3, column k: k must be a finite number in \[-100, 100\], got 'lots' \(not a number\)"),
    ("t,k\n0,0\n0.2,1\n0.1,1\n", r"p\.csv, line 4, column t: times must increase, got 0\.1 after 0\.2"),
    ("t,k,kprime\n0,0,0\n0.1,1,1.5\n", r"p\.csv, line 3, column kprime: kprime must be a number in \[-1, 1\], got '1\.5'"),
    ("t,k\n-1,0\n0.1,1\n", r"p\.csv, line 2, column t: t must be a finite number in \[0, 10000\], got '-1'"),
    ("t,k\n0,0\n0.1,\n", r"p\.csv, line 3, column k: k is missing"),
    ("t,k\n0,0\n", r"p\.csv: 1 sample\(s\); a pulse needs at least two rows"),
    ("", r"p\.csv: empty file; expected a header with columns t,k"),
    ("t,k,t\n0,0,0\n", r"column\(s\) t appear more than once"),
])
def test_pulse_file_errors(tmp_path, text, pattern):
    f = tmp_path / "p.csv"
    f.write_text(text)
    one_error(run("simulate", *MR, "--pulse-file", str(f)), 2, r"'--pulse-file'.*" + pattern)


def test_pulse_file_binary_and_folder(tmp_path):
    b = tmp_path / "b.csv"
    b.write_bytes(bytes(range(256)) * 4)
    one_error(run("simulate", *MR, "--pulse-file", str(b)), 2, r"b\.csv: not a UTF-8 text file \(byte 0x80; save it as UTF-8\)")
    one_error(run("simulate", *MR, "--pulse-file", str(tmp_path)), 2, r"is a (folder|directory)")
    one_error(run("simulate", *MR, "--pulse-file", str(tmp_path / "none.csv")), 2, r"cannot read pulse file")


def test_read_pulse_csv_library(tmp_path):
    from regimemap.motion.file_pulses import read_pulse_csv

    f = tmp_path / "p.csv"
    f.write_text("\ufeffK, T ,note\n\n0,0,a\n0.5,0.1,b\n0,0.2,c\n")
    p = read_pulse_csv(f)
    assert p.shape == "arrays" and float(p.duration) == 0.2 and float(p.k_peak) == 0.5
    assert p.k(np.array([0.05, 0.15, 0.3])).tolist() == pytest.approx([0.25, 0.25, 0.0])


# -- atomic writes ------------------------------------------------------------------------------------

@pytest.mark.parametrize("suffix", ["csv", "npz"])
@pytest.mark.slow
def test_history_write_failing_half_way_leaves_the_old_file(tmp_path, monkeypatch, suffix):
    import builtins

    target = tmp_path / f"h.{suffix}"
    target.write_bytes(b"old")
    real_open = builtins.open

    class Failing:
        def __init__(self, fh):
            self.fh = fh
            self.n = 0

        def write(self, data):
            self.n += 1
            if self.n > 2:
                raise OSError(errno.ENOSPC, "No space left on device")
            return self.fh.write(data)

        def __getattr__(self, name):
            return getattr(self.fh, name)

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            return self.fh.__exit__(*exc)

    def fake_open(file, mode="r", *a, **k):
        fh = real_open(file, mode, *a, **k)
        if str(file).endswith(".part"):
            return Failing(fh)
        return fh

    monkeypatch.setattr(builtins, "open", fake_open)
    r = run("simulate", *MR, *HALF_SINE, "-o", str(target))
    monkeypatch.undo()
    one_error(r, 1, r"cannot write .*No space left on device")
    assert [p.name for p in tmp_path.iterdir()] == [target.name]
    assert target.read_bytes() == b"old"


# -- outcome ------------------------------------------------------------------------------------------

OUT = MR[:6] + ["--mu", "0.5", "--pulse", "half-sine"]


@pytest.mark.slow
@pytest.mark.deep
def test_outcome_npz_and_csv_shapes_and_names(tmp_path):
    npz, csv_path = tmp_path / "m.npz", tmp_path / "m.csv"
    # --no-refine: the grid's arrays are the same bytes (the refined boundaries go to .json and figures
    # only, tests/dynamics/test_outcome_boundaries.py), at a ninth of the cost
    r = run("outcome", *OUT, "--k-peak", "0.3:1.5:7", "--duration", "0.2,0.5,1.2", "--no-refine", "-o", str(npz),
            "-o", str(csv_path))
    assert r.code == 0, r.output
    assert r.stdout.splitlines() == [str(npz), str(csv_path)]
    assert "21 runs" in r.stderr
    with np.load(npz) as z:
        assert z["k_peak"].tolist() == pytest.approx(np.linspace(0.3, 1.5, 7).tolist())
        assert z["duration"].tolist() == [0.2, 0.5, 1.2]
        for key in ("category", "overturned", "max_rotation", "residual_slide"):
            assert z[key].shape == (3, 7), key
        assert list(z["labels"]) == ["rest", "slide only", "rock only", "slide-rock", "overturned", "still moving"]
        assert float(z["mu"]) == 0.5 and str(z["pulse"]) == "half-sine"
        cat = z["category"]
        assert np.array_equal(z["overturned"], cat == 4)
        # the library's map, cell by cell
        sim = simulate(Block(B=0.2, gamma=3.0, mu=0.5), Pulse.half_sine(0.3 + 0.2 * np.arange(7), 1.2),
                       record_phases=False)
        assert np.array_equal(cat[2], sim.category)
    rows = list(csv.DictReader(csv_path.open()))
    assert list(rows[0]) == ["k_peak", "duration", "category", "overturned", "max_rotation", "residual_slide"]
    assert len(rows) == 21 and rows[0]["duration"] == "0.2" and rows[7]["duration"] == "0.5"
    assert {r_["category"] for r_ in rows} <= {"rest", "rock only", "overturned", "slide only", "slide-rock"}


@pytest.mark.slow
def test_outcome_axes_follow_the_command_line_order(tmp_path):
    npz = tmp_path / "m.npz"
    r = run("outcome", *OUT, "--duration", "0.2,0.5", "--k-peak", "0.3:1.5:3", "--no-refine", "-o", str(npz))
    assert r.code == 0, r.output
    with np.load(npz) as z:
        assert z["category"].shape == (3, 2)  # rows k_peak (second), columns duration (first)


@pytest.mark.render
@pytest.mark.deep
def test_outcome_dimensionless_and_figure(tmp_path):
    svg, npz = tmp_path / "s.svg", tmp_path / "s.npz"
    r = run("outcome", *MR, "--pulse", "half-sine", "--omega-p", "3:30:5", "--k-peak", "0.3:2.5:4",
            "--dimensionless", "-o", str(svg), "-o", str(npz))
    assert r.code == 0, r.output
    assert svg.read_text().startswith("<?xml")
    b = Block(B=0.2, gamma=3.0, mu=5.0)
    with np.load(npz) as z:
        np.testing.assert_allclose(z["omega_p_dimensionless"], np.linspace(3, 30, 5) / float(b.p))
        np.testing.assert_allclose(z["k_peak_dimensionless"], np.linspace(0.3, 2.5, 4) / np.tan(float(b.alpha)))


@pytest.mark.parametrize("args,code,pattern", [
    (["--k-peak", "0.3:1.5:3", "--duration", "0.5"], 2, r"give exactly two swept inputs.*swept: --k-peak"),
    (["--k-peak", "0.3:1.5:3", "--duration", "0.5,1", "--mu", "0.4,0.6"], 2, r"exactly two swept.*--mu"),
    (["--k-peak", "0.3,0.3", "--duration", "0.5,1"], 2, r"'--k-peak'.*a value appears twice"),
    (["--k-peak", "0.3:1.5", "--duration", "0.5,1"], 2, r"'--k-peak'.*not start:stop:count"),
    (["--k-peak", "-1,1", "--duration", "0.5,1"], 2, r"'--k-peak'.*k_peak must be a finite number in \[0, 100\]"),
    (["--k-peak", "0:1:3", "--duration", "0:1:3"], 2, r"'--duration'.*start of '0:1:3': duration must be .*\[0\.0001, 100\]"),
    (["--k-peak", "0.1:1:500", "--duration", "0.1:1:501"], 2, r"250500 runs exceed the limit of 250000"),
    (["--k-peak", "0.3,1", "--duration", "0.5,1", "--omega-p", "3"], 2, r"--duration and --omega-p exclude"),
    (["--k-peak", "0.3,1", "--duration", "0.5,1", "-o", "{tmp}/m.gif"], 2, r"'--output'.*\.png, \.svg, \.pdf, \.npz, \.csv"),
    (["--k-peak", "0.3,1", "--gamma", "2,3", "--duration", "0.5", "--dimensionless"], 2,
     r"'--dimensionless'.*--gamma is swept"),
    (["--mu", "0.3,1", "--kprime", "0,0.5", "--duration", "0.5", "--k-peak", "1", "--dimensionless"], 2,
     r"'--dimensionless'.*sweep --k-peak, --duration or --omega-p"),
])
def test_outcome_usage_errors(tmp_path, args, code, pattern):
    base = {"--gamma": "3", "--half-width": "0.2", "--kprime": "0", "--mu": "0.5", "--pulse": "half-sine"}
    extra = [a.replace("{tmp}", str(tmp_path)) for a in args]
    argv = [x for k, v in base.items() if k not in extra for x in (k, v)] + extra
    if "-o" not in argv:
        argv += ["-o", str(tmp_path / "m.npz")]
    one_error(run("outcome", *argv), code, pattern)
    assert list(tmp_path.iterdir()) == []


def test_help_lists_the_commands():
    r = run("--help")
    for name in ("simulate", "outcome", "dynamics-figures"):
        assert name in r.stdout
    for name in ("simulate", "outcome", "dynamics-figures"):
        h = run(name, "--help")
        assert h.code == 0 and "Examples:" in h.stdout


# -- dynamics-figures -----------------------------------------------------------------------------------

@pytest.fixture
def tiny_figures(monkeypatch):
    import dataclasses

    import regimemap.dynamics.presets as dp

    small = {fid: dataclasses.replace(f, first=f.first[:3] + (6,), second=f.second[:3] + (5,))
             for fid, f in list(dp.DYNAMICS_FIGURES.items())[::2]}
    monkeypatch.setattr(dp, "DYNAMICS_FIGURES", small)
    return small


@pytest.mark.render
@pytest.mark.slow
@pytest.mark.deep
def test_dynamics_figures_cache_gives_the_same_bytes(tmp_path, tiny_figures):
    import dataclasses

    fresh, cached = tmp_path / "fresh", tmp_path / "cached"
    fresh.mkdir()
    cached.mkdir()
    cache = tmp_path / "cache"
    # computed afresh (and the cache filled: a computed map is drawn as it is, cache or not), then
    # read from the cache
    r = run("dynamics-figures", "--out", str(fresh), "--format", "svg,png", "--cache", str(cache))
    assert r.code == 0, r.output
    assert "from the cache" not in r.stderr
    r = run("dynamics-figures", "--out", str(cached), "--format", "svg,png", "--cache", str(cache))
    assert r.code == 0, r.output
    assert "from the cache" in r.stderr
    names = sorted(p.name for p in fresh.iterdir())
    assert names == sorted(f.filename(fmt) for f in tiny_figures.values() for fmt in ("svg", "png"))
    for name in names:
        assert (fresh / name).read_bytes() == (cached / name).read_bytes(), name
    assert len(list(cache.glob("*.npz"))) == len(tiny_figures)
    # a changed definition computes again and replaces the figure's cached map
    import regimemap.dynamics.presets as dp

    fid, f = list(tiny_figures.items())[-1]  # D.3: 2 CPU s to compute again (D.1: 11 s)
    dp.DYNAMICS_FIGURES[fid] = dataclasses.replace(f, title="changed")
    r = run("dynamics-figures", "--out", str(cached), "--format", "svg", "--cache", str(cache))
    assert r.code == 0 and f"{fid}: " in r.stderr and "runs)" in r.stderr.split(f"{fid}: ")[1].splitlines()[0]
    assert len(list(cache.glob(f"{fid}-*.npz"))) == 1


def test_dynamics_figures_list_and_errors(tmp_path):
    r = run("dynamics-figures", "--list")
    assert r.code == 0 and [ln.split()[0] for ln in r.stdout.splitlines()] == ["D.1", "D.2", "D.3"]
    one_error(run("dynamics-figures", "--out", str(tmp_path / "none")), 2, r"'--out'.*does not exist")
    one_error(run("dynamics-figures", "--out", str(tmp_path), "--format", "gif"), 2, r"'--format'.*unknown format")
    # a wrong format is refused with --list too, as 'figures --list' refuses it
    one_error(run("dynamics-figures", "--format", "bmp", "--list"), 2, r"'--format'.*unknown format 'bmp'")
    f = tmp_path / "file"
    f.write_text("x")
    one_error(run("dynamics-figures", "--out", str(tmp_path), "--cache", str(f)), 2, r"'--cache'.*not a folder")


def test_figure_ids_cannot_be_mistaken_for_the_report():
    from regimemap.dynamics.presets import DYNAMICS_FIGURE_IDS
    from regimemap.maps.figures.presets import FIGURE_IDS

    assert not set(DYNAMICS_FIGURE_IDS) & set(FIGURE_IDS)
    assert all(Path(f"dyn-{i}.png").name.startswith("dyn-D.") for i in DYNAMICS_FIGURE_IDS)
