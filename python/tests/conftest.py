"""Shared fixtures of the Python package's tests (run on the installed wheel)."""

import os
import pathlib
import shutil

import pytest

#: The repository's root (these tests live in python/tests).
REPO = pathlib.Path(__file__).resolve().parents[2]


def cli_path():
    """The `garmentcode` command-line tool to compare with: $GARMENTCODE_CLI, or
    one on PATH; None when there is none."""
    env = os.environ.get("GARMENTCODE_CLI")
    if env:
        return env
    return shutil.which("garmentcode")


@pytest.fixture
def cli():
    """The CLI binary, or skip (visibly) without it."""
    path = cli_path()
    if path is None and os.environ.get("GARMENTCODE_REQUIRE_CLI"):
        pytest.fail("GARMENTCODE_REQUIRE_CLI is set but there is no CLI: set GARMENTCODE_CLI to the built binary")
    if path is None:
        pytest.skip("no garmentcode CLI to compare with: set GARMENTCODE_CLI to the built binary (.ci/run does)")
    return path


def tree(root):
    """Every file below `root` as {relative path: bytes}."""
    root = pathlib.Path(root)
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}
