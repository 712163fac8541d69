"""The README's Python section runs as written: its install commands are
the ones scripts/test-4-python.sh runs, and its example runs in a fresh
venv that has only the wheel installed (and numpy, its one dependency)."""

import os
import re
import subprocess
import sys

import pytest

from conftest import ROOT


def section() -> str:
    text = (ROOT / "README.md").read_text()
    start = text.index("## Use from Python")
    end = text.find("\n## ", start + 1)
    return text[start : end if end > 0 else None]


def blocks(lang: str):
    return re.findall(rf"```{lang}\n(.*?)```", section(), re.S)


def test_the_install_commands_are_the_tested_ones():
    install = blocks("sh")[0]
    script = (ROOT / "scripts/test-4-python.sh").read_text()
    assert "maturin build --release -m python/Cargo.toml" in install
    assert "maturin\" build --release -m python/Cargo.toml" in script
    assert "pip install target/wheels/placecat-" in install
    assert "python3 -m venv" in install


def test_the_example_runs_in_a_fresh_venv(tmp_path):
    wheel = os.environ.get("PLACECAT_WHEEL")
    if not wheel:
        pytest.skip("PLACECAT_WHEEL unset: run scripts/test-4-python.sh")
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    subprocess.run([str(venv / "bin/pip"), "install", "--quiet", wheel], check=True)
    # The example reads the repository's test scans by relative path, as
    # from a checkout; it runs in a folder of its own (it writes model.json).
    work = tmp_path / "work"
    work.mkdir()
    (work / "tests").symlink_to(ROOT / "tests")
    (work / "example.py").write_text(blocks("python")[0])
    r = subprocess.run([str(venv / "bin/python"), "example.py"], cwd=work, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert "room" in r.stdout and "street" in r.stdout, r.stdout
    assert (work / "model.json").exists()
