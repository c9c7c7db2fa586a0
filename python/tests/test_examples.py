"""examples/python/*.py run (with this interpreter and this PYTHONPATH) and succeed."""
import os
import subprocess
import sys

import pytest

import pendepth
from conftest import REPO

EXAMPLES = sorted((REPO / "examples" / "python").glob("*.py"))


def test_there_are_examples():
    assert len(EXAMPLES) >= 3


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_example_runs(script, tmp_path):
    env = dict(os.environ)  # the package under test, whatever directory the example runs in
    env["PYTHONPATH"] = os.pathsep.join([str(os.path.dirname(os.path.dirname(pendepth.__file__)))] +
                                        ([env["PYTHONPATH"]] if env.get("PYTHONPATH") else []))
    r = subprocess.run([sys.executable, str(script), str(tmp_path)], cwd=tmp_path, env=env,
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout.strip()
