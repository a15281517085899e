"""Every substitution as each frontend writes it: one registration each, as launch's
``@expose_substitution``: its ``$(name ...)``, and the Python callables that make it with the
names of their arguments in the order the ``$(...)`` form takes them. The Python frontend
writes each call as that text (:mod:`rosvar.ros2.frontends.python.calls`); the ROS 2
dialect computes the names it has a handler for (:mod:`rosvar.ros2.substitutions`).
"""

from __future__ import annotations

from dataclasses import dataclass

from rosvar.ros2.api.registry import Registry


@dataclass(frozen=True)
class Signature:
    """A Python callable of a substitution: its qualified name and its arguments' names in
    the order of the ``$(...)`` form, the last ``optional`` of them only when given, the
    last ones with a ``default`` text written as it when not given (the ``$(...)`` form needs
    them); ``variadic``: its positional arguments are the operands, as many as given."""

    qualified: str
    arguments: tuple[str, ...] = ()
    optional: int = 0
    variadic: bool = False
    defaults: tuple[str, ...] = ()
    function: bool = False
    """A function returning the string the substitution gives (``ament_index_python``'s,
    ``os.getenv``), not a substitution object."""
    listed: tuple[str, ...] = ()
    """Arguments launch takes as a list of texts, one item each (``python_modules``), which
    the ``$(...)`` form writes as one comma-separated text."""


@dataclass(frozen=True)
class Substitution:
    names: tuple[str, ...]
    """``$(name ...)``; the first is the one the Python frontend writes."""
    signatures: tuple[Signature, ...] = ()
    """The Python callables that make it."""

    @property
    def python(self) -> tuple[str, ...]:
        return tuple(signature.qualified for signature in self.signatures)


SUBSTITUTIONS: Registry[Substitution] = Registry("substitution")


def expose(name: str, *signatures: Signature) -> Substitution:
    return SUBSTITUTIONS.expose(Substitution((name,), signatures))


# -- launch ---------------------------------------------------------------------------------
expose(
    "var",
    Signature("launch.LaunchConfiguration", ("variable_name", "default"), optional=1),
)
expose(
    "env",
    Signature("launch.EnvironmentVariable", ("name", "default_value"), optional=1),
    # without a default Python gives None where the variable is unset: '' here, which
    # compares, tests false and joins with `or` as None does (known-differences.md)
    Signature("os.getenv", ("key", "default"), defaults=("",), function=True),
    Signature("os.get", ("key", "default"), defaults=("",), function=True),  # os.environ.get
)
expose("find-exec", Signature("launch.FindExecutable", ("name",)))
expose("anon", Signature("launch.AnonName", ("name",)))
expose("filename", Signature("launch.ThisLaunchFile"))
expose("dirname", Signature("launch.ThisLaunchFileDir"))
expose("file-content", Signature("launch.FileContent", ("path",)))
expose("equals", Signature("launch.EqualsSubstitution", ("left", "right")))
expose("not-equals", Signature("launch.NotEqualsSubstitution", ("left", "right")))
expose("and", Signature("launch.AndSubstitution", ("left", "right")))
expose("or", Signature("launch.OrSubstitution", ("left", "right")))
expose("not", Signature("launch.NotSubstitution", ("value",)))
expose("all", Signature("launch.AllSubstitution", variadic=True))
expose("any", Signature("launch.AnySubstitution", variadic=True))
expose(
    "if",
    Signature(
        "launch.IfElseSubstitution", ("condition", "if_value", "else_value"), defaults=("", "")
    ),
)
expose("command", Signature("launch.Command", ("command", "on_stderr"), optional=1))
expose(
    "eval",
    Signature(
        "launch.PythonExpression",
        ("expression", "python_modules"),
        optional=1,
        listed=("python_modules",),
    ),
)

# -- launch_ros, and ament_index_python's functions giving the same paths -------------------
expose(
    "find-pkg-share",
    Signature("launch_ros.FindPackageShare", ("package",)),
    Signature("ament_index_python.get_package_share_directory", ("package_name",), function=True),
)
expose(
    "find-pkg-prefix",
    Signature("launch_ros.FindPackagePrefix", ("package",)),
    Signature("ament_index_python.get_package_prefix", ("package_name",), function=True),
)
expose("exec-in-pkg", Signature("launch_ros.ExecutableInPackage", ("executable", "package")))
expose("param", Signature("launch_ros.Parameter", ("name",)))
