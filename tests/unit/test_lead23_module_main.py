"""``python -m thermobearing`` runs the command line (it failed: no ``__main__``)."""

import subprocess
import sys

from thermobearing import __version__


def test_python_dash_m_runs_the_cli():
    out = subprocess.run([sys.executable, "-m", "thermobearing", "--version"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert __version__ in out.stdout
