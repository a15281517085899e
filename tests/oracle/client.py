"""Client of the roslaunch oracle (``roslaunch_oracle.py``), for differential tests.

The oracle runs under Debian's ``/usr/bin/python3`` (which has ``roslaunch``) in a clean
environment, as one long-lived subprocess that serves any number of jobs. See the docstring of
``roslaunch_oracle.py`` for the job and result formats.

Typical use in a test module::

    from .client import requires_oracle, shared_oracle

    pytestmark = requires_oracle

    def test_something(tmp_path):
        [result] = shared_oracle().run([{"id": 1, "roots": [...], "files": [...]}])

``requires_oracle`` marks the tests ``oracle`` and skips them when the oracle is unavailable.
"""

from __future__ import annotations

import atexit
import contextlib
import functools
import json
import os
import shutil
import subprocess
import tempfile
import threading
from collections.abc import Mapping, Sequence
from pathlib import Path
from types import TracebackType
from typing import IO, Any

import pytest

SYSTEM_PYTHON = "/usr/bin/python3"
ORACLE_SCRIPT = Path(__file__).resolve().with_name("roslaunch_oracle.py")

Job = Mapping[str, Any]
Result = dict[str, Any]


class OracleError(RuntimeError):
    """The oracle process failed (not a failed job: those come back as ``ok: false``)."""


def _clean_env(home: str) -> dict[str, str]:
    return {
        "PATH": "/usr/bin:/bin",
        "HOME": home,
        "ROS_HOME": home,
        "PYTHONDONTWRITEBYTECODE": "1",
    }


@functools.lru_cache(maxsize=1)
def oracle_available() -> bool:
    """True when ``/usr/bin/python3`` exists and imports ``roslaunch``."""
    if not os.access(SYSTEM_PYTHON, os.X_OK) or not ORACLE_SCRIPT.is_file():
        return False
    with tempfile.TemporaryDirectory(prefix="rosvar-oracle-") as home:
        try:
            proc = subprocess.run(
                [SYSTEM_PYTHON, "-c", "import roslaunch.config, roslaunch.xmlloader, rospkg"],
                env=_clean_env(home),
                cwd=home,
                stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
                timeout=60,
                check=False,
            )
        except (OSError, subprocess.SubprocessError):
            return False
    return proc.returncode == 0


UNAVAILABLE_REASON = (
    "roslaunch oracle unavailable: /usr/bin/python3 cannot import roslaunch "
    "(apt-get install python3-roslaunch, or run `make setup`)"
)

#: Marks a test (or, as ``pytestmark``, a module) ``oracle`` and skips it without the oracle.
requires_oracle = [
    pytest.mark.oracle,
    pytest.mark.skipif(not oracle_available(), reason=UNAVAILABLE_REASON),
]


def skip_unless_oracle() -> None:
    """Call inside a test or fixture: skips it when the oracle is unavailable."""
    if not oracle_available():
        pytest.skip(UNAVAILABLE_REASON)


class RoslaunchOracle:
    """One oracle subprocess. ``run`` may be called many times; jobs are answered in order."""

    def __init__(self, python: str = SYSTEM_PYTHON, script: Path | str = ORACLE_SCRIPT) -> None:
        self._python = python
        self._script = str(script)
        self._home: str | None = None
        self._proc: subprocess.Popen[str] | None = None
        self._stderr_file: IO[str] | None = None
        self._lock = threading.Lock()

    # -- process management --------------------------------------------------------------------
    def _start(self) -> subprocess.Popen[str]:
        if self._proc is not None and self._proc.poll() is None:
            return self._proc
        self.close()
        self._home = tempfile.mkdtemp(prefix="rosvar-oracle-")
        self._stderr_file = open(  # noqa: SIM115 - lives as long as the process
            os.path.join(self._home, "oracle.stderr"), "w+", encoding="utf-8"
        )
        self._proc = subprocess.Popen(
            [self._python, self._script],
            env=_clean_env(self._home),
            cwd=self._home,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=self._stderr_file,
            text=True,
            encoding="utf-8",
            bufsize=1,
        )
        return self._proc

    def stderr_tail(self, limit: int = 4000) -> str:
        """The end of what the oracle wrote on stderr (roslaunch's warnings and prints)."""
        if self._stderr_file is None:
            return ""
        self._stderr_file.flush()
        self._stderr_file.seek(0)
        text = self._stderr_file.read()
        self._stderr_file.seek(0, os.SEEK_END)
        return text[-limit:]

    def close(self) -> None:
        proc, self._proc = self._proc, None
        if proc is not None:
            if proc.stdin is not None:
                with contextlib.suppress(OSError):
                    proc.stdin.close()
            try:
                proc.wait(timeout=10)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait()
            if proc.stdout is not None:
                proc.stdout.close()
        if self._stderr_file is not None:
            self._stderr_file.close()
            self._stderr_file = None
        if self._home is not None:
            shutil.rmtree(self._home, ignore_errors=True)
            self._home = None

    def __enter__(self) -> RoslaunchOracle:
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.close()

    # -- jobs ----------------------------------------------------------------------------------
    def run(self, jobs: Sequence[Job]) -> list[Result]:
        """Send all jobs, read all results (one per job, same order)."""
        if not jobs:
            return []
        lines = [json.dumps(dict(job)) + "\n" for job in jobs]
        with self._lock:
            proc = self._start()
            assert proc.stdin is not None and proc.stdout is not None
            stdin, stdout = proc.stdin, proc.stdout
            write_error: list[BaseException] = []

            def writer() -> None:
                try:
                    for line in lines:
                        stdin.write(line)
                    stdin.flush()
                except (OSError, ValueError) as e:  # broken pipe: reported by the reader
                    write_error.append(e)

            thread = threading.Thread(target=writer, daemon=True)
            thread.start()
            results: list[Result] = []
            try:
                for job in jobs:
                    raw = stdout.readline()
                    if not raw:
                        raise OracleError(
                            f"oracle exited (code {proc.poll()}) after {len(results)} of "
                            f"{len(jobs)} jobs; stderr:\n{self.stderr_tail()}"
                        )
                    result: Result = json.loads(raw)
                    if result.get("id") != job.get("id"):
                        raise OracleError(
                            f"oracle answered id {result.get('id')!r} for job {job.get('id')!r}"
                        )
                    results.append(result)
            except BaseException:
                self.close()  # the stream is out of step: start afresh next time
                raise
            finally:
                thread.join()
            if write_error:
                self.close()
                raise OracleError(f"could not send jobs to the oracle: {write_error[0]}")
            return results

    def run_one(self, job: Job) -> Result:
        return self.run([job])[0]


_SHARED: RoslaunchOracle | None = None


def shared_oracle() -> RoslaunchOracle:
    """A process-wide oracle (started on first use, closed at exit). Skips without the oracle."""
    global _SHARED
    skip_unless_oracle()
    if _SHARED is None:
        _SHARED = RoslaunchOracle()
        atexit.register(_SHARED.close)
    return _SHARED
