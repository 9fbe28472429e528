"""pytest fixtures for the MixEngine end-to-end tests (see helpers.py for the environment)."""
import os
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
import helpers  # noqa: E402

_REPORT = []


@pytest.fixture(scope="session")
def engine():
    """The binary under test; a missing binary fails (never skips) every test that needs it."""
    assert helpers.BIN.is_file() and os.access(helpers.BIN, os.X_OK), \
        f"MIXENGINE_BIN={helpers.BIN} is not an executable file (build it first)"
    return helpers.BIN


@pytest.fixture(scope="session")
def corpus():
    """corpus('cube20') -> path of CACHE/cube20.stl; corpus('broken/empty.stl') -> that file.
    Skips when the file is absent, i.e. fetch.sh could not fetch its source."""
    def get(name):
        path = helpers.CORPUS / (name if "." in Path(name).name else f"{name}.stl")
        if not path.is_file():
            pytest.skip(f"corpus file {path} is missing: tests/corpus/fetch.sh could not fetch its source "
                        "(its output names the source)")
        return path
    return get


@pytest.fixture(scope="session")
def report():
    """report(line): a line printed in the 'mixengine report' section after the test run."""
    return _REPORT.append


def pytest_configure(config):
    config.addinivalue_line("markers", "memory: the 2-million-triangle peak-RSS test (deselect: -m 'not memory')")


def pytest_terminal_summary(terminalreporter):
    if _REPORT:
        terminalreporter.write_sep("-", "mixengine report")
        for line in _REPORT:
            terminalreporter.write_line(line)
