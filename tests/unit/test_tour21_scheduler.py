"""User tour 21, oil-flow what-if sweep on a dask scheduler: ``--scheduler`` pointed at a
port where another service answers in its own protocol (an SSH server's banner).

Before the fix the sweep's error quoted dask's decoding failure as the reason ("MemoryError:
Unable to allocate 2.82 EiB for an array ..."), and the half-started dask Client, left to the
garbage collector, waited 10 s on the dead connection at interpreter exit and printed
"Exception ignored in: <function Client.__del__ ...> ... TimeoutError".
"""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from thermobearing.scene import load_scene
from thermobearing.sweep import SchedulerUnreachable, parse_set, run_sweep

BANNER = b"SSH-2.0-OpenSSH_8.9p1 Ubuntu-3ubuntu0.1\r\n"


def _serve_banner(srv: socket.socket, stop: threading.Event, conns: list) -> None:
    srv.settimeout(0.1)
    while not stop.is_set():
        try:
            conn = srv.accept()[0]
        except OSError:
            continue
        conns.append(conn)
        try:
            conn.sendall(BANNER)
        except OSError:
            pass


@pytest.fixture()
def banner_server():
    """A TCP server that greets every connection with an SSH banner and then waits."""
    srv = socket.socket()
    srv.bind(("127.0.0.1", 0))
    srv.listen(8)
    conns: list = []
    stop = threading.Event()
    th = threading.Thread(target=_serve_banner, args=(srv, stop, conns), daemon=True)
    th.start()
    yield f"tcp://127.0.0.1:{srv.getsockname()[1]}"
    stop.set()
    th.join(1.0)
    for c in conns:
        c.close()
    srv.close()


def _runner(scene_toml: str) -> dict[str, float]:
    return {"value [-]": 1.0}


def test_service_answering_another_protocol_is_named_as_such(tmp_path, banner_server):
    scene = load_scene()
    p = parse_set("supply.flow=15,33", scene.to_dict())
    with pytest.raises(SchedulerUnreachable) as info:
        run_sweep(scene, [p], tmp_path / "a", runner=_runner, scheduler=banner_server,
                  progress=False, connect_timeout=1.0)
    msg = str(info.value)
    assert "something answered there, but not as a dask scheduler" in msg
    assert "usually 8786" in msg
    assert "--fallback-local" in msg
    assert not (tmp_path / "a" / "cases.jsonl").exists()


def test_failed_client_is_closed_not_left_to_interpreter_exit(banner_server):
    # the traceback of Client.__del__ appears at interpreter exit: a fresh interpreter
    code = (
        "import sys\n"
        "from thermobearing.sweep import SchedulerUnreachable, _dask_client\n"
        "try:\n"
        f"    _dask_client({banner_server!r}, 1.0)\n"
        "except SchedulerUnreachable as exc:\n"
        "    print('unreachable:', exc)\n"
        "else:\n"
        "    sys.exit('connected to a banner server')\n"
    )
    root = Path(__file__).resolve().parents[2]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(root), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env=env, timeout=120)
    assert done.returncode == 0, done.stderr
    assert "unreachable:" in done.stdout
    assert "Exception ignored" not in done.stderr, done.stderr
    assert "Client.__del__" not in done.stderr, done.stderr
