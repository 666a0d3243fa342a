"""The loads on the command line: options and their errors, classify, points files, export
round trips, and atlas / animate sweeping a load."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest
from PIL import Image

from regimemap import Mode, Parameters, classify, label_grid
from regimemap.maps.file_points import read_points_csv

GODA = ["--gamma", "0.7", "--kprime", "-0.018", "--buoyancy", "0.318", "--uplift-ratio", "0.524"]
GODA_P = Parameters(0.7, -0.018, buoyancy=0.318, uplift_ratio=0.524)


@pytest.mark.parametrize("option,value,message", [
    ("--buoyancy", "1", r"buoyancy must be a number in [0, 1), got '1'"),
    ("--buoyancy", "-0.1", r"buoyancy must be a number in [0, 1), got '-0.1'"),
    ("--uplift", "-1", r"uplift must be a number in [0, 1e+06], got '-1'"),
    ("--uplift-ratio", "nan", r"uplift_ratio must be a number in [0, 1e+06], got 'nan'"),
    ("--uplift-arm", "1.5", r"uplift_arm must be a number in [-1, 1], got '1.5'"),
    ("--gyration", "0", r"gyration must be a number in [0.001, 1000], got '0'"),
    ("--gyration", "1e-300", r"gyration must be a number in [0.001, 1000], got '1e-300'"),
    ("--crest", "x", r"crest must be a number in (0, 1000], got 'x' (not a number)"),
])
@pytest.mark.parametrize("command", ["plot", "classify", "export"])
def test_bad_load_exits_2_naming_option_and_range(run_cli, tmp_path, command, option, value,
                                                  message):
    extra = {"plot": ["-o", str(tmp_path / "m.png")], "export": ["-o", str(tmp_path / "m.json")],
             "classify": ["--k", "0.3", "--mu", "0.5"]}[command]
    r = run_cli([command, "--gamma", "3", "--kprime", "0.4", option, value, *extra])
    assert r.code == 2, r.output
    assert f"Invalid value for '{option}': {message}" in r.stderr
    assert list(tmp_path.iterdir()) == []


def test_kprime_up_to_the_crest(run_cli, tmp_path):
    r = run_cli(["export", "--gamma", "3", "--kprime", "1.2", "--crest", "1.1", "-o",
                 str(tmp_path / "m.json")])
    assert r.code == 2 and "'--kprime': kprime must be a number in [-1, 1.1], got '1.2'" in r.stderr
    r = run_cli(["export", "--gamma", "3", "--kprime", "1.05", "--crest", "1.1", "-o",
                 str(tmp_path / "m.json")])
    assert r.code == 0, r.output
    r = run_cli(["plot", "--gamma", "3", "--kprime", "1.5", "-o", str(tmp_path / "m.png")])
    assert r.code == 2 and "kprime must be a number in [-1, 1], got '1.5'" in r.stderr


@pytest.mark.render
def test_plot_with_loads(run_cli, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    r = run_cli(["plot", *GODA, "--resolution", "201", "--dpi", "40"])
    assert r.code == 0, r.output
    assert (tmp_path / "regime-g0.7-kp-0.018-b0.318-nu0.524.png").is_file()


def test_classify_reports_loads_and_least_constraint(run_cli):
    r = run_cli(["classify", *GODA, "--k", "4", "--mu", "3"])
    assert r.code == 0, r.output
    assert "loads     beta = 0.318, u = 0, nu = 0.524, e_u = 1/3" in r.stdout
    assert "mode      LO" in r.stdout and "admissible (solver): LO, RO, SRO-" in r.stdout
    assert "chosen by least" in r.stdout
    assert "margin" in r.stdout and "-> RO" in r.stdout
    r = run_cli(["classify", *GODA, "--k", "4", "--mu", "3", "--json"])
    d = json.loads(r.stdout)
    assert d["chosen_by"] == "least constraint" and d["loads"]["buoyancy"] == 0.318
    assert d["admissible"] == ["LO", "RO", "SRO-"]


def test_points_csv_load_columns(run_cli, tmp_path):
    f = tmp_path / "pts.csv"
    f.write_text("name,k,mu,buoyancy,uplift_ratio,uplift_arm,gyration,crest,uplift\n"
                 "air,0.28,0.6,,,,,,\n"
                 "sea,0.28,0.6,0.318,0.524,,,,\n"
                 "far,4,3,0.318,0.524,0.3333333333333333,,1,0\n")
    pts = read_points_csv(f)
    assert pts[0].loads == {} and pts[1].loads == {"buoyancy": 0.318, "uplift_ratio": 0.524}
    out = tmp_path / "res.csv"
    r = run_cli(["classify", "--points", str(f), "--gamma", "0.7", "--kprime", "-0.018", "-o",
                 str(out)])
    assert r.code == 0, r.output
    rows = list(csv.DictReader(out.read_text(encoding="utf-8").splitlines()))
    assert [row["mode"] for row in rows] == ["RE", "RE", "LO"]
    assert rows[0]["buoyancy"] == "" and rows[1]["buoyancy"] == "0.318"
    assert rows[2]["chosen_by"] == "least constraint" and rows[1]["chosen_by"] == "unique"
    # the loads move the margin: sliding comes closer under water (Goda's SF_s = 1.16)
    assert float(rows[1]["margin_k"]) < float(rows[0]["margin_k"])


def test_points_csv_bad_load(tmp_path):
    f = tmp_path / "pts.csv"
    f.write_text("k,mu,buoyancy\n0.1,0.2,1\n")
    with pytest.raises(ValueError, match=r"line 2, column buoyancy: buoyancy must be a number "
                                         r"in \[0, 1\), got '1'"):
        read_points_csv(f)
    f.write_text("k,mu,kprime,crest\n0.1,0.2,1.2,1.1\n")
    with pytest.raises(ValueError, match=r"column kprime: kprime must be a number in \[-1, 1.1\]"):
        read_points_csv(f)
    f.write_text("k,mu,kprime,crest\n0.1,0.2,1.05,1.1\n")
    assert read_points_csv(f)[0].crest == 1.1


def test_export_npz_round_trip_with_loads(run_cli, tmp_path):
    out = tmp_path / "m.npz"
    r = run_cli(["export", *GODA, "--resolution", "80", "-o", str(out)])
    assert r.code == 0, r.output
    assert "beta = 0.318, nu = 0.524, e_u = 1/3" in r.stderr
    with np.load(out) as z:
        assert bool(z["loaded"]) and float(z["buoyancy"]) == 0.318
        assert float(z["uplift_ratio"]) == 0.524 and np.isnan(z["gyration"])
        assert float(z["k_L"]) == GODA_P.k_L
        p = Parameters(float(z["gamma"]), float(z["kprime"]), buoyancy=float(z["buoyancy"]),
                       uplift=float(z["uplift"]), uplift_ratio=float(z["uplift_ratio"]),
                       uplift_arm=float(z["uplift_arm"]), crest=float(z["crest"]))
        assert np.array_equal(z["mode"], label_grid(z["k"], z["mu"], p.gamma, p.kprime, **p.loads))
        assert (z["mode"] == Mode.LO).any()


def test_export_csv_round_trip_with_loads(run_cli, tmp_path):
    out = tmp_path / "m.csv"
    r = run_cli(["export", *GODA, "--resolution", "12", "-o", str(out)])
    assert r.code == 0, r.output
    rows = list(csv.DictReader(out.read_text(encoding="utf-8").splitlines()))
    assert list(rows[0]) == ["k", "mu", "mode", "gamma", "kprime", "buoyancy", "uplift_ratio",
                             "uplift_arm"]
    k = np.array([float(r_["k"]) for r_ in rows])
    mu = np.array([float(r_["mu"]) for r_ in rows])
    codes = classify(k, mu, 0.7, -0.018, buoyancy=0.318, uplift_ratio=0.524)
    assert [Mode(int(c)).label for c in codes] == [r_["mode"] for r_ in rows]
    # the rows read back as design points with their loads (classify --points)
    pts = read_points_csv(out)
    # numbers for people: 12 significant digits (1/3 reads 0.333333333333)
    assert pts[0].loads == {"buoyancy": 0.318, "uplift_ratio": 0.524, "uplift_arm": 0.333333333333}


@pytest.mark.slow
def test_export_json_with_loads(run_cli, tmp_path):
    out = tmp_path / "m.json"
    r = run_cli(["export", *GODA, "-o", str(out)])
    assert r.code == 0, r.output
    g = json.loads(out.read_text())
    assert g["parameters"]["buoyancy"] == 0.318 and g["parameters"]["gyration"] is None
    assert g["lift_off"]["k_L"] == float(f"{GODA_P.k_L:.12g}")  # 12 significant digits
    assert "LO" in g["modes"] and g["regions"]["LO"] and "LO" in g["curves"]
    assert g["curves"]["LO"]["polylines"][0][0] == [float(f"{GODA_P.k_L:.12g}"), 0.0]
    # {LO, RO, SRO-} lies above mu = 1.2: in the report's view, not the designer's
    assert not any("least constraint" in a["label"] for a in g["ambiguity"])
    r = run_cli(["export", *GODA, "--view", "report", "-o", str(out)])
    assert r.code == 0, r.output
    g = json.loads(out.read_text())
    assert any("least constraint" in a["label"] for a in g["ambiguity"])
    # the report's block keeps its file: no loads, no lift-off
    r = run_cli(["export", "--gamma", "3", "--kprime", "0.4", "-o", str(tmp_path / "z.json")])
    z = json.loads((tmp_path / "z.json").read_text())
    assert "lift_off" not in z and "LO" not in z["modes"] and set(z["parameters"]) == {"gamma",
                                                                                       "kprime"}


@pytest.mark.render
@pytest.mark.slow
def test_atlas_sweeps_a_load(run_cli, tmp_path):
    out = tmp_path / "a.svg"
    r = run_cli(["atlas", "--gamma", "0.7", "--kprime", "-0.018", "--uplift-ratio", "0.524",
                 "--buoyancy", "0,0.3,0.6", "-o", str(out)])
    assert r.code == 0, r.output
    assert "1 x 3 panels, columns buoyancy" in r.stderr
    text = out.read_text()
    assert text.count('id="panel-0-') == 3


def test_atlas_one_sweep_per_axis(run_cli, tmp_path):
    r = run_cli(["atlas", "--gamma", "0.7", "--kprime", "0,0.2", "--buoyancy", "0,0.3", "-o",
                 str(tmp_path / "a.png")])
    assert r.code == 2 and "one quantity per axis: --kprime and --buoyancy" in r.stderr
    r = run_cli(["atlas", "--gamma", "0.7", "--kprime", "0", "--buoyancy", "0,1", "-o",
                 str(tmp_path / "a.png")])
    assert r.code == 2 and "'--buoyancy': buoyancy must be a number in [0, 1)" in r.stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.render
@pytest.mark.slow
def test_animate_sweeps_the_uplift_ratio(run_cli, tmp_path):
    out = tmp_path / "nu.gif"
    r = run_cli(["animate", "--gamma", "0.7", "--kprime", "-0.018", "--buoyancy", "0.318",
                 "--uplift-ratio", "0:1:3", "--dpi", "30", "-o", str(out)])
    assert r.code == 0, r.output
    with Image.open(out) as im:
        assert im.n_frames == 3


@pytest.mark.render
def test_atlas_figure_panel_titles_and_key_with_loads():
    from regimemap.maps.figures.atlas import atlas_figure
    from regimemap.maps.run_atlas import run_atlas

    fig = atlas_figure(run_atlas([0.7], [0.0, 0.5], sweep="uplift_ratio",
                                 fixed={"kprime": -0.018, "buoyancy": 0.318}, samples=101, k_max=6.0))
    titles = [ax.get_title(loc="left") for ax in fig.axes]
    assert titles == [r"$\gamma = 0.7$, $\nu = 0$", r"$\gamma = 0.7$, $\nu = 0.5$"]
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert Mode.LO.description in labels
    assert r"$\beta = 0.318$" in fig._suptitle.get_text()
