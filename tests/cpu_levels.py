"""``make test-portable``: the tests marked ``portable`` again, at each of numpy's dispatch levels.

numpy compiles its loops (exp, log, sin, power ...) for several CPU feature levels and picks, at
import, the highest one the CPU has; the levels' loops differ in the last bits.  So that a test
which holds only on the developer's CPU fails here rather than on a user's, this script runs
``pytest -m portable`` once per level of this CPU above numpy's baseline, the highest first, with
``NPY_DISABLE_CPU_FEATURES`` naming that level and every level above it -- on an AVX-512 x86-64
machine ``X86_V4 ...`` (numpy's AVX2 loops, as on an AVX2-only CPU), then ``X86_V3 X86_V4 ...``
(the baseline loops, as on an older CPU).

What numpy (2.x) accepts in ``NPY_DISABLE_CPU_FEATURES``: the names of its dispatch targets
(``numpy._core._multiarray_umath.__cpu_dispatch__``, e.g. X86_V3 X86_V4 AVX512_ICL AVX512_SPR);
a target this CPU lacks is accepted and changes nothing; any other name is ignored with an
``ImportWarning``; a baseline feature (X86_V2) stops numpy's import with a ``RuntimeError``.  The
levels are therefore taken from ``__cpu_dispatch__``, kept to those this CPU has, and of those
only the ones some ufunc loop is compiled for (``numpy.lib.introspect.opt_func_info``; all of
them on a numpy without it).  A CPU with none (numpy's baseline only, as on many ARM machines)
has nothing to compare: the script says so and passes.

Usage: ``python tests/cpu_levels.py [PYTEST OPTIONS]``; exit status 1 if a level fails.  Only the
files that mark a test ``portable`` are collected (a text search for ``mark.portable``).
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

_VARIABLE = "NPY_DISABLE_CPU_FEATURES"

#: What a test file that marks a test portable contains.
MARK = "mark.portable"

#: Printed in each level's process: where numpy's float64 exp, log, sin and power now dispatch.
_SHOW = """
from numpy.lib import introspect
info = introspect.opt_func_info(func_name="exp|log|sin|power", signature="float64")
print(sorted({s["current"] for f in info.values() for s in f.values()}))
"""


def _features() -> tuple[list[str], dict[str, bool], set[str] | None]:
    """numpy's dispatch targets (lowest first), this CPU's features, the targets loops use."""
    try:
        from numpy._core import _multiarray_umath as umath
    except ImportError:  # numpy 1.x
        from numpy.core import _multiarray_umath as umath  # type: ignore[no-redef]
    used: set[str] | None = None
    try:
        from numpy.lib.introspect import opt_func_info  # numpy >= 2.1
    except ImportError:
        pass
    else:
        used = {target for sigs in opt_func_info().values() for s in sigs.values()
                for target in s["available"].split()}
    return list(umath.__cpu_dispatch__), dict(umath.__cpu_features__), used


def levels() -> tuple[list[list[str]], list[str]]:
    """The values of NPY_DISABLE_CPU_FEATURES to run under (the highest level dropped first), and
    a line for each dispatch target left out and why.

    Read in this process, so the caller's own NPY_DISABLE_CPU_FEATURES must be unset
    (``main`` does so before numpy is imported).
    """
    dispatch, features, used = _features()
    have = [t for t in dispatch if features.get(t)]
    steps = [t for t in have if used is None or t in used]
    notes = [f"{t}: not on this CPU" for t in dispatch if t not in have]
    for t in have:
        if t not in steps:
            below = [u for u in steps if have.index(u) < have.index(t)]
            notes.append(f"{t}: no ufunc loop is compiled for it"
                         + (f" (disabled together with {below[-1]})" if below else ""))
    return [have[have.index(t):] for t in reversed(steps)], notes


def marked_files() -> list[str]:
    """The test files that mark tests ``portable`` (collecting only these is much quicker)."""
    here = Path(__file__).resolve().parent
    return sorted(str(f.relative_to(here.parent)) for f in here.rglob("test_*.py")
                  if MARK in f.read_text(encoding="utf-8"))


def _run(disabled: list[str], args: list[str]) -> tuple[bool, float]:
    env = dict(os.environ, **{_VARIABLE: " ".join(disabled)})
    shown = subprocess.run([sys.executable, "-c", _SHOW], env=env, capture_output=True, text=True)
    where = shown.stdout.strip() or shown.stderr.strip().splitlines()[-1:]
    print(f"\n== {_VARIABLE}={' '.join(disabled)!r}: float64 exp, log, sin, power run {where}",
          flush=True)
    t0 = time.perf_counter()
    code = subprocess.run([sys.executable, "-m", "pytest", "-m", "portable", *args, *marked_files()],
                          env=env, cwd=Path(__file__).resolve().parents[1]).returncode
    return code == 0, time.perf_counter() - t0


def main(args: list[str]) -> int:
    if os.environ.pop(_VARIABLE, None) is not None:
        print(f"{_VARIABLE} was set: ignored, each level sets its own")
    todo, notes = levels()
    for note in notes:
        print(f"test-portable: {note}")
    if not todo:
        import numpy as np

        print("test-portable: numpy runs its baseline loops only on this CPU (no dispatch level "
              f"above the baseline; numpy {np.__version__}): nothing to compare, nothing run")
        return 0
    results = [(disabled, *_run(disabled, args)) for disabled in todo]
    print()
    for disabled, ok, seconds in results:
        print(f"test-portable: {'passed' if ok else 'FAILED'} with {_VARIABLE}="
              f"{' '.join(disabled)!r} ({seconds:.1f} s)")
    return 0 if all(ok for _, ok, _ in results) else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
