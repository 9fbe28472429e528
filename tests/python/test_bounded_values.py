"""Issue 29 item 4 (bounded work on any input): a setting value the engine evaluates as a Python expression
(Cura sends list settings such as machine_disallowed_areas as Python text, read by the formula evaluator)
ends with one error line naming the key, not with gigabytes of memory.

Before the fix, `-s machine_disallowed_areas=[[0,0,[0,0,0,]]*120*1*1,0,[0,0,0,]]*120*1555` took the engine
to 18 GB in 60 s: Python shares the repeated inner list, the engine's values deep-copy it (67 million items).
Each evaluation now has a budget of 1,000,000 list items and string characters and 1,000,000 steps
(engine/settings/formula/Budget.h). The peak RSS of the engine (GNU time's %M) must stay under
MEMORY_BOUND_MIB; the child runs under an address-space limit so that a regression fails the test instead of
taking the shared machine's memory. No timing threshold: the timeout only guards against a hang.
"""
import os
import resource
import subprocess
import tempfile
from pathlib import Path

import pytest

import helpers
import mixing_gcode

MEMORY_BOUND_MIB = 100
ADDRESS_SPACE_LIMIT = 4 << 30  # the child's RLIMIT_AS: a regression aborts instead of eating the machine
TIMEOUT_S = 120

TOO_LARGE = "too large (more than 1000000 elements: list items and string characters)"
REPETITION = "[[0,0,[0,0,0,]]*120*1*1,0,[0,0,0,]]*120*1555"  # the value of the issue (b)
POLYGON = "[[-20, 10]*999999, [10, 10], [0, -5]]*999999"  # the settings fuzz finding (a), as a value
COMPREHENSION = "[0 for a in 'grid' * 5000 for b in 'grid' * 5000 if a + b == '']"  # the formula one (c)


def limit_address_space():
    resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE_LIMIT, ADDRESS_SPACE_LIMIT))


def peak_rss_run(cmd):
    """Runs cmd; returns (exit code, peak RSS in bytes, stderr lines). Kills it after TIMEOUT_S (a hang).

    The engine runs under GNU time, which reports its child's ru_maxrss. Measured from here instead (os.wait4 on
    a child of this process), the figure would include this Python process's own high-water mark: Linux keeps the
    larger of the old and new memory's peak across fork and exec, so a 16 MiB engine read 112 MiB under a pytest
    run of the whole suite."""
    env = dict(os.environ, **helpers.CURA_ENV)
    with tempfile.TemporaryDirectory() as scratch:  # not the test's folder: it checks that nothing is left there
        report = Path(scratch) / "peak_rss_kib"
        timed = ["/usr/bin/time", "-f", "%M", "-o", str(report), *map(str, cmd)]
        with subprocess.Popen(timed, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env,
                              preexec_fn=limit_address_space) as proc:
            try:
                _, stderr = proc.communicate(timeout=TIMEOUT_S)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.communicate()
                pytest.fail(f"mixengine did not finish within {TIMEOUT_S} s: {cmd}")
        peak_kib = int(report.read_text().split()[-1])  # after "Command exited with non-zero status N"
    return proc.returncode, peak_kib * 1024, stderr.decode(errors="replace").splitlines()


def assert_one_error_within_bound(cmd, expected_line):
    rc, rss, lines = peak_rss_run(cmd)
    assert rc == 1, f"exit {rc}, expected 1; stderr: {lines[:5]}"
    assert lines == [expected_line]
    assert rss < MEMORY_BOUND_MIB << 20, f"peak RSS {rss / 2**20:.0f} MiB, bound {MEMORY_BOUND_MIB} MiB"


def expected_error(value, problem):
    return f"mixengine: error: setting 'machine_disallowed_areas': formula '{value}': {problem}"


def test_slice_with_repeated_list_value_is_one_error(engine, tmp_path):
    model = mixing_gcode.box_stl(tmp_path / "cube.stl", 20, 20, 20)
    out = tmp_path / "out.gcode"
    cmd = [str(engine), "slice", "-s", f"machine_disallowed_areas={REPETITION}", "-l", str(model), "-o", str(out)]
    assert_one_error_within_bound(cmd, expected_error(REPETITION, TOO_LARGE))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cube.stl"], "output left behind after an error"


@pytest.mark.parametrize("value, problem", [(REPETITION, TOO_LARGE), (POLYGON, TOO_LARGE),
                                            (COMPREHENSION, TOO_LARGE)],
                         ids=["repetition", "polygon", "comprehension"])
def test_settings_with_explosive_value_is_one_error(engine, value, problem):
    cmd = [str(engine), "settings", "-s", f"machine_disallowed_areas={value}"]
    assert_one_error_within_bound(cmd, expected_error(value, problem))
