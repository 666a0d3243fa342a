"""Every example of README.md runs (shell blocks with the installed `regimemap`, Python blocks)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

README = Path(__file__).resolve().parents[1] / "README.md"
BIN = str(Path(sys.executable).parent)


def _blocks() -> list[tuple[str, str]]:
    out = []
    for lang, body in re.findall(r"```(\w+)\n(.*?)```", README.read_text(encoding="utf-8"), re.S):
        if lang == "console":
            cmds = [line[2:].split("  #")[0] for line in body.splitlines() if line.startswith("$ ")]
            body = "\n".join(c for c in cmds if not c.startswith("make "))
            lang = "sh"
        elif lang in ("sh", "bash"):
            if "make figures" in body or "make test" in body:
                continue  # the README's set-up commands: CI runs `make test` itself
            body = body.replace(".venv/bin/", "")
        elif lang != "python":
            continue
        if body.strip():
            out.append((lang, body))
    return out


BLOCKS = _blocks()


def test_readme_has_examples():
    langs = {lang for lang, _ in BLOCKS}
    assert {"sh", "python"} <= langs and len(BLOCKS) >= 10


def test_readme_examples_run(tmp_path):
    """Blocks run in order in one folder (later examples use files that earlier ones write)."""
    env = dict(os.environ, PATH=BIN + os.pathsep + os.environ.get("PATH", ""), MPLBACKEND="Agg")
    for lang, body in BLOCKS:
        cmd = [sys.executable, "-c", body] if lang == "python" else ["bash", "-e", "-c", body]
        r = subprocess.run(cmd, cwd=tmp_path, env=env, capture_output=True, text=True, timeout=300)
        assert r.returncode == 0, f"README example failed:\n{body}\n--- stderr ---\n{r.stderr[-2000:]}"
