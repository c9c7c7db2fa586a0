"""examples/python/*.py run (with this interpreter and this PYTHONPATH) and succeed."""
import os
import re
import subprocess
import sys

import pytest

import pendepth
from conftest import REPO

EXAMPLES = sorted((REPO / "examples" / "python").glob("*.py"))


def package_env():
    """The environment of a child interpreter that imports the package under test from any directory."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(os.path.dirname(os.path.dirname(pendepth.__file__)))] +
                                        ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    return env


def test_there_are_examples():
    assert len(EXAMPLES) >= 3


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_example_runs(script, tmp_path):
    env = package_env()
    r = subprocess.run([sys.executable, str(script), str(tmp_path)], cwd=tmp_path, env=env,
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.strip()


def test_readme_python_block_runs(tmp_path):
    """README's Python block is a quick start users paste: it must run as written."""
    text = (REPO / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert len(blocks) == 1
    env = package_env()
    r = subprocess.run([sys.executable, "-c", blocks[0]], cwd=tmp_path, env=env,
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.strip()
