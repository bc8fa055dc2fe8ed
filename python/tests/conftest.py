"""Shared fixtures: the unfurl command (for comparisons with the CLI) and scratch directories."""
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def unfurl_binary():
    path = os.environ.get("UNFURL_BINARY")
    if not path or not os.path.exists(path):
        pytest.skip("UNFURL_BINARY is not set (ctest sets it)")
    return path


@pytest.fixture
def cli(unfurl_binary):
    def run(*args):
        done = subprocess.run([unfurl_binary, *args], capture_output=True, text=True)
        assert done.returncode == 0, done.stdout + done.stderr
        return done.stdout
    return run
