"""The worked example of docs/python.md runs as written: its Python blocks, in order, in a fresh
folder that sees the project's data/ (as the page's commands assume the checkout's root)."""
import os
import re
import subprocess
import sys

from conftest import DATA, SOURCE


def test_the_worked_example_runs(tmp_path):
    page = (SOURCE / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", page, flags=re.S)
    assert len(blocks) >= 2
    (tmp_path / "data").symlink_to(DATA)
    (tmp_path / "example.py").write_text("\n".join(blocks))
    done = subprocess.run([sys.executable, "example.py"], cwd=tmp_path, capture_output=True,
                          text=True, env=dict(os.environ, MPLBACKEND="Agg"), timeout=300)
    assert done.returncode == 0, done.stderr
    for method in ("hybrid", "mmas", "acs"):
        assert re.search(rf"^{re.escape(method)} +weight \d+\.\d+ \+- \d+\.\d+", done.stdout,
                         flags=re.M), done.stdout
    assert (tmp_path / "convergence.png").stat().st_size > 1000
