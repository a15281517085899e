#!/usr/bin/python3
"""roslaunch oracle: load launch configurations with the REAL roslaunch loader, print them as JSON.

Run with Debian's ``/usr/bin/python3`` (package ``python3-roslaunch``, roslaunch 1.15.15). This
is the oracle of rosvar's differential tests. It never starts anything: no master, no nodes, no
``command=`` parameter is executed (process creation is disabled in this interpreter).

Protocol
========

Input: JSON lines on stdin, one job per line::

    {"id": ANY, "roots": [DIR, ...], "files": [PATH, ...],
     "args": {"NAME": "VALUE"}, "env": {"NAME": "VALUE"}, "rescan": false}

Output: exactly one JSON line per job on stdout, in the same order, flushed after each line. Nothing
else is ever written to stdout (roslaunch's own prints go to stderr). One process serves any number
of jobs; roslaunch is imported once.

* ``roots``: package roots. ``$(find pkg)`` uses a ``rospkg.RosPack(ros_paths=roots)`` put into
  ``roslaunch.substitution_args._rospack``; one RosPack is cached per distinct roots tuple for the
  life of the process (packages are found by ``package.xml`` alone; metapackages are not found by
  ``$(find)``, as in rospack). Set ``"rescan": true`` when packages under the same roots changed
  since an earlier job.
  catkin workspaces are not consulted (neither ``CMAKE_PREFIX_PATH`` nor the ``/usr`` that
  Debian's catkin adds), so ``$(find pkg)/path`` never resolves into ``/usr/share/<pkg>``.
* ``files``: loaded in order into one configuration with
  ``roslaunch.config.load_config_default([(f, argv), ...], None, loader=XmlLoader(), verbose=False,
  assign_machines=False)``.
* ``args``: command-line args, given to every file as ``argv = ["NAME:=VALUE", ...]`` exactly as
  ``roslaunch pkg file NAME:=VALUE`` does, so the rules of ``rosgraph.names.load_mappings`` apply
  (a name with one leading ``_`` is ignored; ``__ns:=`` sets the root namespace; a value containing
  ``:=`` is dropped).
* ``env``: the WHOLE process environment during the job (read by ``$(env)``, ``$(optenv)``, eval's
  ``env()``/``optenv()``, ``ROS_NAMESPACE``, ``ROS_DISTRO``, ...). Nothing of the oracle's own
  environment is visible (no ambient ``ROS_NAMESPACE``, ``ROS_DISTRO``, ``HOME``, ...), with one
  exception: ``ROS_PACKAGE_PATH`` is always set to ``":".join(roots)`` (overriding any value in
  ``env``), so ``$(env ROS_PACKAGE_PATH)`` sees it. Variables given in ``env`` act as in real
  roslaunch, e.g. ``ROS_NAMESPACE`` moves the root namespace. The environment is restored after
  the job.

Output on success::

    {"id": ID, "ok": true,
     "nodes": [NODE, ...],          # sorted by "name"
     "tests": [TEST, ...],          # sorted by "name"
     "params": {FULL_NAME: VALUE},  # keys sorted
     "machines": {NAME: MACHINE},   # keys sorted; roslaunch's implicit local machine "" left out
     "clear_params": [NS, ...],     # sorted (duplicates kept)
     "warnings": [STR, ...]}        # ROSLaunchConfig.config_errors, in order

    NODE = {"name": ns_join(namespace, name), "namespace": STR (ends with "/"), "package": STR,
            "type": STR, "args": STR, "remaps": [[FROM, TO], ...] (sorted), "respawn": BOOL,
            "respawn_delay": FLOAT, "required": BOOL, "machine": STR|null (machine name),
            "launch_prefix": STR|null, "cwd": STR|null, "output": STR|null,
            "env": [[NAME, VALUE], ...] (sorted), "filename": STR}
    TEST = NODE + {"test_name": STR, "time_limit": FLOAT, "retry": INT}
    MACHINE = {"address": STR, "env_loader": STR, "ssh_port": INT, "user": STR|null,
               "password": STR|null, "assignable": BOOL, "timeout": FLOAT}

  A machine without ``env-loader`` gets roslaunch's guess ``/opt/ros/<distro>/env.sh`` where
  ``<distro>`` comes from ``ROS_DISTRO`` in the job env (``None`` when unset: there is no
  ``/etc/ros/distro``).

Parameter values: bool, int, float and str as is (floats nan/inf/-inf as the strings ``"nan"``,
``"inf"``, ``"-inf"``); dicts and lists recursively (non-string dict keys become ``str(key)``);
YAML null as null; ``xmlrpc.client.Binary`` (``binfile=``, ``!!binary``) and bytes as
``{"__binary__": BASE64}``; date/datetime as ``{"__datetime__": ISO}``; anything else as
``{"__repr__": repr(value)}``. Parameters of roslaunch's own ``roscore.xml`` (``/rosversion``,
``/rosdistro``) are left out unless a launch file overrode them; its core node ``/rosout`` is never
listed (but, as in roslaunch, a launch-file node named ``/rosout`` is a duplicate-name error).

``command=`` parameters: never executed. The value is ``convert_value("__command__(CMD)", type)``
where CMD is the command string after substitution (not stripped, not shlex-split), i.e. exactly
what roslaunch would do with a command whose output is ``__command__(CMD)``.

``$(anon ID)``: roslaunch's random ``rosgraph.names.anonymous_name`` is replaced by a deterministic
one: the n-th call within a job (n = 1, 2, ... in evaluation order; roslaunch calls it once per
distinct ID per substitution context, and contexts are copied into child scopes) returns
``f"{ID}_anon{n}"`` with ``.``, ``-`` and ``:`` replaced by ``_`` (the same screening roslaunch
applies to its random names). rosvar produces the same names.

Machines: ``assign_machines=False`` because roslaunch's machine assignment resolves every machine
address through DNS (``is_machine_local``), which is environment-dependent. Its only
configuration check is replicated after loading: a node or test (in that order) naming a machine
that was never declared fails with ``RLException("ERROR: unknown machine [NAME]")``.

Output on failure::

    {"id": ID, "ok": false, "error": str(exc), "error_type": type(exc).__name__, "outside": BOOL}

``outside`` is true when the failure comes from something outside the launch files themselves. The
exception and every exception in its ``__cause__``/``__context__`` chain are inspected; ``outside``
is true if any of them

1. is a ``rospkg.ResourceNotFound`` (a ``$(find pkg)``/``find()`` of a package found in no root), or
   has a message containing ``"The following package was not found"`` or ``"package not found"``;
2. has a message containing ``"environment variable "`` ... ``" is not set"`` (``$(env X)`` or eval
   ``env('X')`` with X missing from the job env);
3. reports a missing file (``FileNotFoundError.filename``, ``"No such file or directory: 'P'"``,
   ``"file does not exist [P]"``) whose path P is absolute and lies in no package directory (a
   directory holding ``package.xml``) found under the job's roots, e.g. a hard-coded
   ``/opt/ros/...`` path or a ``$(dirname)/../../other_pkg/...`` path to a package that is absent.
   A missing file inside a package that exists, or a relative path, is a launch-file error.

Everything else (bad XML, missing required arg, unused include args, duplicate node names, invalid
attribute values, ...) has ``outside: false``. A malformed input line gives
``{"id": null, "ok": false, "error": ..., "error_type": "OracleInputError", "outside": false}``.
"""

from __future__ import annotations

import base64
import copy
import datetime
import json
import logging
import math
import os
import re
import subprocess
import sys
import traceback
import xmlrpc.client
from typing import ClassVar

# --------------------------------------------------------------------------------------------------
# stdout hygiene: keep a private handle on the real stdout, then point fd 1 and sys.stdout at stderr
# so that anything roslaunch (or anything else) prints cannot corrupt the JSON stream.
_OUT = os.fdopen(os.dup(1), "w", encoding="utf-8", newline="\n")
os.dup2(2, 1)
sys.stdout = sys.stderr

import catkin.find_in_workspaces  # noqa: E402
import rosgraph.names  # noqa: E402
import roslaunch.config  # noqa: E402
import roslaunch.core  # noqa: E402
import roslaunch.loader  # noqa: E402
import roslaunch.substitution_args  # noqa: E402
import roslaunch.xmlloader  # noqa: E402
import rospkg  # noqa: E402
import rospkg.common  # noqa: E402
import rospkg.rospack  # noqa: E402
import yaml  # noqa: E402

logging.getLogger("roslaunch").setLevel(logging.CRITICAL)


# --------------------------------------------------------------------------------------------------
# Never run anything.
class _NoProcess(RuntimeError):
    pass


def _forbidden(*_args, **_kwargs):
    raise _NoProcess("roslaunch oracle: starting a process is forbidden")


class _ForbiddenPopen:
    def __init__(self, *_args, **_kwargs):
        _forbidden()


subprocess.Popen = _ForbiddenPopen
for _fn in (
    "system",
    "popen",
    "fork",
    "forkpty",
    "execv",
    "execve",
    "execvp",
    "execvpe",
    "spawnv",
    "spawnve",
    "spawnvp",
    "spawnvpe",
    "posix_spawn",
    "posix_spawnp",
):
    if hasattr(os, _fn):
        setattr(os, _fn, _forbidden)


# --------------------------------------------------------------------------------------------------
# command= params: value is "__command__(CMD)", converted like a command's output.
_orig_param_value = roslaunch.loader.Loader.param_value


def _param_value(self, verbose, name, ptype, value, textfile, binfile, command):
    if value is None and textfile is None and binfile is None and command is not None:
        return roslaunch.loader.convert_value(f"__command__({command})", ptype)
    return _orig_param_value(self, verbose, name, ptype, value, textfile, binfile, command)


roslaunch.loader.Loader.param_value = _param_value


# --------------------------------------------------------------------------------------------------
# $(find pkg)/path first asks catkin.find_in_workspaces (CMAKE_PREFIX_PATH workspaces, plus the
# /usr that Debian's catkin always appends, where /usr/share/roslaunch etc. live). The job's roots
# must be the only package universe, so no catkin workspace is consulted: $(find) then behaves as
# upstream roslaunch with no workspace (executable file or plain path under rospack's package dir).
catkin.find_in_workspaces.find_in_workspaces = lambda *args, **kwargs: []


# --------------------------------------------------------------------------------------------------
# Speed: PyYAML's pure-Python SafeLoader dominates batch runs (the same YAML files are loaded by
# many jobs). Memoize yaml.safe_load by text; each call gets a deep copy; errors are not cached.
# The results are identical to uncached parsing.
import rosparam  # noqa: E402, F401  (registers its YAML constructors, as roslaunch does)

_orig_safe_load = yaml.safe_load
_YAML_CACHE = {}


def _safe_load(stream):
    if not isinstance(stream, str):
        return _orig_safe_load(stream)
    try:
        data = _YAML_CACHE[stream]
    except KeyError:
        data = _orig_safe_load(stream)
        if len(_YAML_CACHE) >= 4096:
            _YAML_CACHE.clear()
        _YAML_CACHE[stream] = data
    return copy.deepcopy(data)


yaml.safe_load = _safe_load


# --------------------------------------------------------------------------------------------------
# Deterministic $(anon id).
class _Anon:
    count = 0


def _anonymous_name(id):  # same signature as rosgraph.names.anonymous_name
    _Anon.count += 1
    name = f"{id}_anon{_Anon.count}"
    return name.replace(".", "_").replace("-", "_").replace(":", "_")


rosgraph.names.anonymous_name = _anonymous_name
try:
    import roslib.names

    roslib.names.anonymous_name = _anonymous_name
except Exception:  # pragma: no cover - roslib is optional
    pass


# --------------------------------------------------------------------------------------------------
# roscore.xml parameters: remember the Param objects roscore put in the config.
class _Core:
    params: ClassVar[dict] = {}


_orig_load_roscore = roslaunch.config.load_roscore


def _load_roscore(loader, config, verbose=True):
    _orig_load_roscore(loader, config, verbose=verbose)
    _Core.params = dict(config.params)


roslaunch.config.load_roscore = _load_roscore


# --------------------------------------------------------------------------------------------------
# Package roots.
_ROSPACKS = {}
_PACKAGE_DIRS = {}


def _rospack_for(roots, rescan):
    key = tuple(roots)
    if rescan or key not in _ROSPACKS:
        _ROSPACKS[key] = rospkg.RosPack(ros_paths=list(roots))
        _PACKAGE_DIRS.pop(key, None)
    return _ROSPACKS[key]


def _package_dirs(roots):
    """Real paths of every directory holding a package.xml (metapackages included) in roots."""
    key = tuple(roots)
    dirs = _PACKAGE_DIRS.get(key)
    if dirs is None:
        dirs = set()
        for root in roots:
            cache = {}
            if os.path.isdir(root):
                rospkg.rospack.list_by_path(rospkg.common.PACKAGE_FILE, root, cache)
            dirs.update(os.path.realpath(d) for d in cache.values())
        _PACKAGE_DIRS[key] = dirs
    return dirs


# --------------------------------------------------------------------------------------------------
# JSON encoding.
def _encode(value):
    if isinstance(value, bool) or value is None or isinstance(value, (int, str)):
        return value
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return value
    if isinstance(value, dict):
        return {(k if isinstance(k, str) else str(k)): _encode(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_encode(v) for v in value]
    if isinstance(value, xmlrpc.client.Binary):
        return {"__binary__": base64.b64encode(value.data).decode("ascii")}
    if isinstance(value, (bytes, bytearray)):
        return {"__binary__": base64.b64encode(bytes(value)).decode("ascii")}
    if isinstance(value, (datetime.date, datetime.datetime)):
        return {"__datetime__": value.isoformat()}
    return {"__repr__": repr(value)}


def _node_json(n):
    d = {
        "name": rosgraph.names.ns_join(n.namespace, n.name) if n.name else None,
        "namespace": n.namespace,
        "package": n.package,
        "type": n.type,
        "args": n.args,
        "remaps": sorted([list(r) for r in n.remap_args]),
        "respawn": n.respawn,
        "respawn_delay": _encode(n.respawn_delay),
        "required": n.required,
        "machine": n.machine_name,
        "launch_prefix": n.launch_prefix,
        "cwd": n.cwd,
        "output": n.output,
        "env": sorted([list(e) for e in n.env_args]),
        "filename": n.filename,
    }
    if isinstance(n, roslaunch.core.Test):
        d["test_name"] = n.test_name
        d["time_limit"] = _encode(n.time_limit)
        d["retry"] = n.retry
    return d


def _machine_json(m):
    return {
        "address": m.address,
        "env_loader": m.env_loader,
        "ssh_port": m.ssh_port,
        "user": m.user,
        "password": m.password,
        "assignable": m.assignable,
        "timeout": _encode(m.timeout),
    }


def _sort_key(d):
    return (d["name"] or "", d["package"], d["type"])


def _config_json(config):
    params = {
        key: _encode(p.value) for key, p in config.params.items() if _Core.params.get(key) is not p
    }
    return {
        "nodes": sorted((_node_json(n) for n in config.nodes), key=_sort_key),
        "tests": sorted((_node_json(t) for t in config.tests), key=_sort_key),
        "params": dict(sorted(params.items())),
        "machines": {
            name: _machine_json(m) for name, m in sorted(config.machines.items()) if name != ""
        },
        "clear_params": sorted(config.clear_params),
        "warnings": list(config.config_errors),
    }


# --------------------------------------------------------------------------------------------------
# Failure classification.
_PKG_MSGS = ("The following package was not found", "package not found")
_ENV_RE = re.compile(r"environment variable .* is not set", re.S)
_MISSING_RES = (
    re.compile(r"No such file or directory: '([^']*)'"),
    re.compile(r"file does not exist \[([^\]]*)\]"),
)


def _chain(exc):
    seen = set()
    while exc is not None and id(exc) not in seen:
        seen.add(id(exc))
        yield exc
        exc = exc.__cause__ if exc.__cause__ is not None else exc.__context__


def _message(exc):
    try:
        return str(exc)
    except Exception:
        return ""


def _is_outside(exc, roots):
    missing = []
    for e in _chain(exc):
        msg = _message(e)
        if isinstance(e, rospkg.ResourceNotFound) or any(m in msg for m in _PKG_MSGS):
            return True
        if _ENV_RE.search(msg):
            return True
        if isinstance(e, FileNotFoundError) and isinstance(e.filename, str):
            missing.append(e.filename)
        for rx in _MISSING_RES:
            missing.extend(rx.findall(msg))
    if missing:
        pkg_dirs = _package_dirs(roots)
        for path in missing:
            if not os.path.isabs(path):
                continue
            p = os.path.realpath(path)
            inside_pkg = False
            while True:
                if p in pkg_dirs:
                    inside_pkg = True
                    break
                parent = os.path.dirname(p)
                if parent == p:
                    break
                p = parent
            if not inside_pkg:
                return True
    return False


# --------------------------------------------------------------------------------------------------
# Jobs.
def _check_machines(config):
    for n in list(config.nodes) + list(config.tests):
        if n.machine_name and n.machine_name not in config.machines:
            raise roslaunch.core.RLException(f"ERROR: unknown machine [{n.machine_name}]")


def _run_job(job):
    roots = [str(r) for r in job.get("roots", [])]
    files = [str(f) for f in job.get("files", [])]
    args = job.get("args") or {}
    env = {str(k): str(v) for k, v in (job.get("env") or {}).items()}
    argv = [f"{k}:={v}" for k, v in args.items()]

    saved_env = dict(os.environ)
    saved_rospack = roslaunch.substitution_args._rospack
    _Anon.count = 0
    _Core.params = {}
    try:
        os.environ.clear()
        os.environ.update(env)
        os.environ["ROS_PACKAGE_PATH"] = ":".join(roots)
        roslaunch.substitution_args._rospack = _rospack_for(roots, bool(job.get("rescan")))
        try:
            config = roslaunch.config.load_config_default(
                [(f, list(argv)) for f in files],
                None,
                loader=roslaunch.xmlloader.XmlLoader(),
                verbose=False,
                assign_machines=False,
            )
            _check_machines(config)
            result = {"id": job.get("id"), "ok": True}
            result.update(_config_json(config))
            return result
        except (Exception, SystemExit) as e:
            return {
                "id": job.get("id"),
                "ok": False,
                "error": _message(e),
                "error_type": type(e).__name__,
                "outside": _is_outside(e, roots),
            }
    finally:
        os.environ.clear()
        os.environ.update(saved_env)
        roslaunch.substitution_args._rospack = saved_rospack


def _write(obj):
    try:
        line = json.dumps(obj, allow_nan=False)
    except (TypeError, ValueError) as e:
        line = json.dumps(
            {
                "id": obj.get("id") if isinstance(obj.get("id"), (str, int, float)) else None,
                "ok": False,
                "error": f"oracle could not encode the result: {e}",
                "error_type": "OracleEncodeError",
                "outside": False,
            }
        )
    _OUT.write(line + "\n")
    _OUT.flush()


def main():
    for raw in sys.stdin:
        if not raw.strip():
            continue
        try:
            job = json.loads(raw)
            if not isinstance(job, dict):
                raise ValueError("a job must be a JSON object")
        except ValueError as e:
            _write(
                {
                    "id": None,
                    "ok": False,
                    "error": f"bad job line: {e}",
                    "error_type": "OracleInputError",
                    "outside": False,
                }
            )
            continue
        try:
            result = _run_job(job)
        except BaseException as e:  # never kill the batch (KeyboardInterrupt aside)
            if isinstance(e, KeyboardInterrupt):
                raise
            traceback.print_exc(file=sys.stderr)
            result = {
                "id": job.get("id"),
                "ok": False,
                "error": _message(e),
                "error_type": type(e).__name__,
                "outside": False,
            }
        _write(result)


if __name__ == "__main__":
    main()
