"""``rosvar serve``: the configuration engine built once, then the web UI served on it."""

from __future__ import annotations

import argparse
import contextlib
import sys
import time

from rosvar.outputs.commands.exit_codes import EXIT_OK, EXIT_USAGE
from rosvar.outputs.commands.loading import analysis_with_env, interfaces_of
from rosvar.outputs.commands.terminal import building, progress


def cmd_serve(options: argparse.Namespace) -> int:
    from rosvar.analyses.feature_model.extraction import extract
    from rosvar.configuration.engine import Configurator
    from rosvar.outputs.web.entries import render
    from rosvar.outputs.web.server import make_server

    loaded = analysis_with_env(options)
    if isinstance(loaded, int):
        return loaded
    analysis, env = loaded
    started = time.perf_counter()
    files = len(analysis.workspace.launch_files)
    print(f"rosvar: analysing {files} launch files ...", file=sys.stderr, flush=True)
    model = extract(analysis, progress=progress, products=True, env=env)
    interfaces = interfaces_of(analysis.workspace, options)
    configurator = Configurator(
        analysis,
        model,
        env,
        progress=building(tty_only=False),
        interfaces=interfaces,
        render=render,
    )
    try:
        server = make_server(configurator, options.host, options.port)
    except OSError as error:
        print(f"rosvar: cannot listen on {options.host}:{options.port}: {error}", file=sys.stderr)
        return EXIT_USAGE
    print(f"rosvar: ready in {time.perf_counter() - started:.1f} s", file=sys.stderr)
    print(f"rosvar: serving {server.url} (Ctrl-C stops)", flush=True)
    with server, contextlib.suppress(KeyboardInterrupt):  # Ctrl-C is how it stops
        server.serve_forever()
    return EXIT_OK
