"""The package as people get it: its version, licence, changelog and citation, and the sdist and
wheel that ``python -m build`` makes, installed into a fresh virtual environment.

The version comes from git through setuptools-scm (pyproject.toml, ``[tool.setuptools_scm]``):
a tag vX.Y.Z is X.Y.Z, commits after it X.Y.(Z+1).devN+g<hash>, no tag 0.1.devN+g<hash>, no git
at all the fallback.  The distributions are built once per session (``dists``) from a copy of
the working tree committed to a repository of its own (so that neither the tree's git nor its
``src/regimemap/_version.py`` is touched), with ``--no-isolation`` (the build requirements are in
the ``test`` extra): the sdist from git's files, the wheel from the unpacked sdist, as
``python -m build`` does for a release.
"""

from __future__ import annotations

import datetime
import importlib.metadata
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import zipfile
from dataclasses import dataclass
from pathlib import Path

import pytest
from click.testing import CliRunner
from packaging.version import Version

import regimemap
from regimemap.cli import cli

if sys.version_info >= (3, 11):
    import tomllib
else:  # the standard library's TOML reader before Python 3.11 (a dependency there)
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
#: The report regimemap implements, as README.md and CITATION.cff name it.
REPORT_TITLE = "Behavior of a Freestanding Rigid Body Subjected to a Horizontal Force"
#: Keep a Changelog's kinds of change.
CHANGE_KINDS = {"Added", "Changed", "Deprecated", "Removed", "Fixed", "Security"}


# -- version, licence, changelog, citation --------------------------------------------------------


def test_version_is_the_installed_distributions():
    """``regimemap.__version__`` (the file setuptools-scm writes) is what the installed metadata
    says, a PEP 440 version, and what ``regimemap --version`` prints."""
    installed = importlib.metadata.version("regimemap")
    assert regimemap.__version__ == installed, (
        "src/regimemap/_version.py and the installed metadata disagree: a build in the tree "
        "rewrote the file; `pip install -e .` (make venv) writes both again")
    assert str(Version(installed)) == installed
    res = CliRunner().invoke(cli, ["--version"])
    assert res.exit_code == 0
    assert res.output == f"regimemap, version {installed}\n"


def _clean_env(**extra: str) -> dict[str, str]:
    """The environment less what would point a child at this tree, its git or its interpreter."""
    env = {k: v for k, v in os.environ.items()
           if not k.startswith("GIT_") and k not in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV")}
    env.update(GIT_CONFIG_NOSYSTEM="1", GIT_CONFIG_GLOBAL=os.devnull, MPLBACKEND="Agg", **extra)
    return env


def _git(where: Path, *args: str) -> str:
    out = subprocess.run(["git", "-c", "user.name=regimemap tests", "-c", "user.email=tests@invalid",
                          "-c", "commit.gpgsign=false", "-c", "tag.gpgsign=false", *args],
                         cwd=where, capture_output=True, text=True, env=_clean_env())
    assert out.returncode == 0, out.stderr
    return out.stdout


def _scm_version(where: Path) -> str:
    out = subprocess.run([sys.executable, "-m", "setuptools_scm"], cwd=where, capture_output=True,
                         text=True, env=_clean_env())
    assert out.returncode == 0, out.stderr
    return out.stdout.strip()


@pytest.mark.subprocess
def test_version_from_git_tags(tmp_path):
    """The project's setuptools-scm settings: the fallback without git, 0.1.devN without a tag,
    the tag's version on it, the next patch's dev version after it."""
    pytest.importorskip("setuptools_scm")
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    shutil.copy(ROOT / "pyproject.toml", tmp_path)
    assert _scm_version(tmp_path) == PYPROJECT["tool"]["setuptools_scm"]["fallback_version"]
    _git(tmp_path, "init", "-q")
    _git(tmp_path, "commit", "-q", "--allow-empty", "-m", "first")
    assert re.fullmatch(r"0\.1\.dev1\+g[0-9a-f]{7,}", _scm_version(tmp_path))
    _git(tmp_path, "tag", "-a", "v0.2.0", "-m", "0.2.0")
    assert _scm_version(tmp_path) == "0.2.0"
    _git(tmp_path, "commit", "-q", "--allow-empty", "-m", "second")
    assert re.fullmatch(r"0\.2\.1\.dev1\+g[0-9a-f]{7,}", _scm_version(tmp_path))


def test_licence_is_bsd_3_clause():
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("BSD 3-Clause License\n")
    assert "Copyright (c) 2026, regimemap developers" in text
    assert PYPROJECT["project"]["license"] == "BSD-3-Clause"
    assert PYPROJECT["project"]["license-files"] == ["LICENSE"]


@dataclass
class Release:
    version: str
    date: str | None  # None for [Unreleased]
    kinds: dict[str, list[str]]  # kind of change -> its bullets


def _changelog() -> tuple[list[str], list[Release]]:
    """The lines of CHANGELOG.md before the first release, and its releases in file order."""
    head: list[str] = []
    releases: list[Release] = []
    kind = ""
    for line in (ROOT / "CHANGELOG.md").read_text(encoding="utf-8").splitlines():
        if line.startswith("## "):
            m = re.fullmatch(r"## \[(Unreleased|\d+\.\d+\.\d+)\](?: - (\d{4}-\d{2}-\d{2}))?", line)
            assert m, f"release heading {line!r}: '## [X.Y.Z] - YYYY-MM-DD' or '## [Unreleased]'"
            releases.append(Release(m[1], m[2], {}))
        elif line.startswith("### "):
            kind = line[4:]
            assert kind in CHANGE_KINDS, f"{line!r}: one of {sorted(CHANGE_KINDS)}"
            assert kind not in releases[-1].kinds, f"{line!r} twice in {releases[-1].version}"
            releases[-1].kinds[kind] = []
        elif line.startswith("- "):
            releases[-1].kinds[kind].append(line)
        elif not releases:
            head.append(line)
    return head, releases


def test_changelog_keeps_a_changelog():
    head, releases = _changelog()
    assert head[0] == "# Changelog"
    assert "reconstructed" in " ".join(head)  # the versions before the first tag say so
    assert releases[0].version == "Unreleased" and releases[0].date is None
    versions = [Version(r.version) for r in releases[1:]]
    dates = [datetime.date.fromisoformat(r.date) for r in releases[1:] if r.date]
    assert len(dates) == len(versions) >= 1, "every release has its date"
    assert versions == sorted(versions, reverse=True) and len(set(versions)) == len(versions)
    assert dates == sorted(dates, reverse=True)
    for r in releases[1:]:
        assert r.kinds and all(r.kinds.values()), f"{r.version}: a heading without a change"


def test_citation_names_the_software_and_the_report():
    """CITATION.cff: the keys CFF 1.2.0 requires, the licence of pyproject.toml, the version and
    date of the changelog's latest release, and the report under references."""
    yaml = pytest.importorskip("yaml")
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert {"cff-version", "message", "title", "authors"} <= set(cff)
    assert cff["cff-version"] == "1.2.0" and cff["type"] == "software"
    assert all("name" in a or "family-names" in a for a in cff["authors"])
    assert cff["license"] == PYPROJECT["project"]["license"]
    latest = _changelog()[1][1]
    assert (cff["version"], cff["date-released"]) == (latest.version, latest.date)
    (report,) = [r for r in cff["references"] if r["type"] == "report"]
    assert report["title"] == REPORT_TITLE
    assert REPORT_TITLE in " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    assert report["year"] == 2005 and report["authors"][0]["family-names"] == "Tung"
    assert {"title", "authors", "year", "institution"} <= set(report)


# -- the distributions ----------------------------------------------------------------------------

#: Names that no distribution carries: version control, environments, caches, build products,
#: CI's script.
NEVER_SHIPPED = {".git", ".venv", ".cache", ".ci", "_build", "auto_examples", "__pycache__",
                 ".pytest_cache", ".hypothesis", ".mypy_cache", ".ruff_cache", "build", "dist"}


@dataclass
class Dists:
    tree: Path  # the copy the distributions were built from
    sdist: Path
    wheel: Path
    version: str


def _source_files(root: Path) -> list[str]:
    """The working tree's files: git's (tracked, and untracked but not ignored) in a checkout,
    else every file outside the names of NEVER_SHIPPED (an unpacked sdist)."""
    if (root / ".git").exists():
        listed = _git(root, "ls-files", "-z", "--cached", "--others", "--exclude-standard")
        return [f for f in listed.split("\0") if f and (root / f).is_file()]
    return [str(p.relative_to(root)) for p in root.rglob("*")
            if p.is_file() and not NEVER_SHIPPED & set(p.relative_to(root).parts)
            and not any(part.endswith(".egg-info") for part in p.parts)]


@pytest.fixture(scope="session")
def dists(tmp_path_factory) -> Dists:
    """``python -m build --no-isolation`` on a committed copy of the working tree."""
    pytest.importorskip("build")
    pytest.importorskip("setuptools_scm")
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    tmp = tmp_path_factory.mktemp("dists")
    tree = tmp / "regimemap"
    for name in _source_files(ROOT):
        (tree / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / name, tree / name)
    # what a working copy holds besides its sources (git ignores them): no distribution takes them
    for decoy in ("docs/_build/html/index.html", ".cache/dynamics-figures/map.npz",
                  "src/regimemap/__pycache__/x.pyc"):
        (tree / decoy).parent.mkdir(parents=True, exist_ok=True)
        (tree / decoy).write_text("not a source\n", encoding="utf-8")
    _git(tree, "init", "-q")
    _git(tree, "add", "-A")
    _git(tree, "commit", "-q", "-m", "the working tree")
    out = subprocess.run([sys.executable, "-m", "build", "--no-isolation", "--outdir", str(tmp / "dist"),
                          str(tree)], capture_output=True, text=True, env=_clean_env())
    assert out.returncode == 0, out.stdout[-3000:] + out.stderr[-3000:]
    (sdist,) = (tmp / "dist").glob("*.tar.gz")
    (wheel,) = (tmp / "dist").glob("*.whl")
    version = sdist.name.removeprefix("regimemap-").removesuffix(".tar.gz")
    return Dists(tree, sdist, wheel, version)


@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_sdist_holds_the_sources_not_the_products(dists):
    # one commit and no tag: setuptools-scm's version
    assert re.fullmatch(r"0\.1\.dev1\+g[0-9a-f]{7,}", dists.version), dists.version
    with tarfile.open(dists.sdist) as tar:
        names = {m.name.split("/", 1)[1] for m in tar.getmembers() if m.isfile()}
    # the package, its tests and the documentation's sources, all of them
    sources = {f for f in _source_files(dists.tree)
               if f.split("/")[0] in ("src", "tests", "docs", "bench")
               and not NEVER_SHIPPED & set(Path(f).parts)}
    assert sources - names == set()
    assert {"LICENSE", "README.md", "CHANGELOG.md", "CITATION.cff", "pyproject.toml", "PKG-INFO",
            "conftest.py", "src/regimemap/py.typed", "src/regimemap/_version.py"} <= names
    # of the committed figures, the README's only
    shown = set(re.findall(r"\]\((figures/[^)]+)\)", (ROOT / "README.md").read_text(encoding="utf-8")))
    assert shown and {n for n in names if n.startswith("figures/")} == shown
    assert [n for n in names if NEVER_SHIPPED & set(Path(n).parts)] == []


@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_wheel_holds_the_package_and_its_licence(dists):
    with zipfile.ZipFile(dists.wheel) as whl:
        names = set(whl.namelist())
        (info,) = {n.split("/")[0] for n in names} - {"regimemap"}
        metadata = whl.read(f"{info}/METADATA").decode()
        version_file = whl.read("regimemap/_version.py").decode()
    package = {f.removeprefix("src/") for f in _source_files(dists.tree) if f.startswith("src/regimemap/")}
    assert {n for n in names if n.startswith("regimemap/")} == package | {"regimemap/_version.py"}
    assert f"{info}/licenses/LICENSE" in names
    assert "License-Expression: BSD-3-Clause" in metadata.splitlines()
    assert f"Version: {dists.version}" in metadata.splitlines()
    assert f'__version__ = "{dists.version}"' in version_file


@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_twine_check_passes(dists):
    pytest.importorskip("twine")
    out = subprocess.run([sys.executable, "-m", "twine", "check", "--strict", str(dists.sdist),
                          str(dists.wheel)], capture_output=True, text=True, env=_clean_env())
    assert out.returncode == 0, out.stdout + out.stderr


@pytest.mark.subprocess
@pytest.mark.slow
@pytest.mark.deep
def test_installed_wheel_runs_outside_the_tree(dists, tmp_path):
    """The wheel in a fresh virtual environment (its dependencies lent by this one through a .pth
    file, no network): the command, a figure and the library, run from a folder outside the tree,
    import the installed package."""
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
    scripts = venv / ("Scripts" if os.name == "nt" else "bin")
    python = scripts / "python"
    env = _clean_env()
    pip = subprocess.run([sys.executable, "-m", "pip", "--python", str(python), "install", "--quiet",
                          "--no-deps", "--no-index", str(dists.wheel)], capture_output=True, text=True,
                         env=env)
    assert pip.returncode == 0, pip.stdout + pip.stderr
    site = subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                          capture_output=True, text=True, check=True, env=env).stdout.strip()
    lent = {sysconfig.get_path("purelib"), sysconfig.get_path("platlib")}
    Path(site, "_dependencies.pth").write_text("\n".join(sorted(lent)) + "\n", encoding="utf-8")
    work = tmp_path / "work"
    work.mkdir()

    def run(*args: str) -> str:
        out = subprocess.run(list(args), cwd=work, capture_output=True, text=True, env=env)
        assert out.returncode == 0, out.stderr
        return out.stdout

    assert run(str(scripts / "regimemap"), "--version") == f"regimemap, version {dists.version}\n"
    run(str(scripts / "regimemap"), "plot", "--gamma", "3", "--kprime", "0.4", "-o", "x.svg")
    svg = (work / "x.svg").read_text(encoding="utf-8")
    release = re.match(r"\d+(?:\.\d+)*", dists.version).group(0)  # figures name the release
    assert svg.startswith("<?xml") and f"regimemap {release}<" in svg, svg[:800]  # the figure's Creator
    code = ("import importlib.metadata, regimemap\n"
            "print(regimemap.__file__)\n"
            "print(importlib.metadata.version('regimemap'), regimemap.__version__)\n"
            "print(regimemap.Mode(int(regimemap.classify(0.5, 0.8, gamma=3.0, kprime=0.4))).name)\n")
    file, versions, mode = run(str(python), "-c", code).splitlines()
    assert Path(file).resolve().is_relative_to(venv.resolve())
    assert not Path(file).resolve().is_relative_to(ROOT)
    assert versions == f"{dists.version} {dists.version}"
    assert mode == regimemap.Mode(int(regimemap.classify(0.5, 0.8, gamma=3.0, kprime=0.4))).name
