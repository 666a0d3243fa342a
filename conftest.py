"""pytest settings for the whole tree: the tests (tests/) and the doctests of src/regimemap.

matplotlib draws with Agg (no window, no display): set before any module imports pyplot,
including the library modules that ``--doctest-modules`` imports to run their examples.
The doctests of the drawing modules are marked ``render``, so ``make test-fast`` leaves them out.
The tests run longest first (see ``pytest_collection_modifyitems``).
"""

from __future__ import annotations

import os

import matplotlib
import pytest

matplotlib.use("Agg")

#: Library packages whose docstring examples draw figures.
_RENDERING_PACKAGES = ("regimemap.drawing",)


def _cost(item: pytest.Item) -> int:
    """0 for the long tests that start processes (the README's examples, all the figures, process
    pools), 1 for the other long ones, then those that start processes, those that draw, the rest."""
    slow, subprocess, render = (item.get_closest_marker(m) is not None
                                for m in ("slow", "subprocess", "render"))
    return 0 if slow and subprocess else 1 if slow else 2 if subprocess else 3 if render else 4


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    for item in items:
        if type(item).__name__ == "DoctestItem" and item.name.startswith(_RENDERING_PACKAGES):
            item.add_marker(pytest.mark.render)
    # The long tests first (a stable sort: the order within each tier is the files' own), so that
    # on several cores (pytest-xdist) none of them starts last while the other cores idle.  Every
    # worker collects the same order: the sort depends on the marks only.
    items.sort(key=_cost)


#: The environment every test runs in, whatever the developer's shell exports (the processes the
#: tests start inherit it): REGIMEMAP_DEBUG would print tracebacks where a test expects one line,
#: REGIMEMAP_DASK_TIMEOUT would change how long a scheduler is tried, and MPLBACKEND a GUI
#: backend would try to open windows in the ``python -c`` and ``regimemap`` processes.
PINNED_ENVIRONMENT: dict[str, str | None] = {"REGIMEMAP_DEBUG": None, "REGIMEMAP_DASK_TIMEOUT": None,
                                             "MPLBACKEND": "Agg"}


@pytest.fixture(autouse=True, scope="session")
def _pinned_environment():
    """:data:`PINNED_ENVIRONMENT` for the whole session (a test may still set them for itself)."""
    with pytest.MonkeyPatch.context() as mp:
        for name, value in PINNED_ENVIRONMENT.items():
            if value is None:
                mp.delenv(name, raising=False)
            else:
                mp.setenv(name, value)
        yield


@pytest.fixture(autouse=True)
def _check_the_tier(request: pytest.FixtureRequest, monkeypatch: pytest.MonkeyPatch):
    """With ``REGIMEMAP_CHECK_TIERS=1``, a test that draws a figure without the ``render`` mark, or
    starts a process without the ``subprocess`` mark, fails: the marks stay true as tests are added.

    ``REGIMEMAP_CHECK_TIERS=1 make test-fast`` checks the fast tier (off by default: it patches
    matplotlib's Figure, subprocess.Popen and multiprocessing for every test).
    """
    if not os.environ.get("REGIMEMAP_CHECK_TIERS"):
        yield
        return
    import multiprocessing.process
    import subprocess

    from matplotlib.figure import Figure

    def guard(mark: str, what: str, real):
        if request.node.get_closest_marker(mark) is not None:
            return real

        def refuse(*args, **kwargs):
            pytest.fail(f"{request.node.nodeid} {what} but is not marked {mark!r} "
                        f"(@pytest.mark.{mark}: make test-fast leaves it out)", pytrace=False)
        return refuse

    monkeypatch.setattr(Figure, "__init__", guard("render", "draws a figure", Figure.__init__))
    monkeypatch.setattr(subprocess.Popen, "__init__",
                        guard("subprocess", "starts a process", subprocess.Popen.__init__))
    monkeypatch.setattr(multiprocessing.process.BaseProcess, "start",
                        guard("subprocess", "starts a process", multiprocessing.process.BaseProcess.start))
    yield

