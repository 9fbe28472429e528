"""The complexity check fails, naming the function, on a fixture above the limit, and passes at it."""
import pathlib

import complexity_check


def branchy_function(name, branches):
    """C++ source of a function `name` with CCN 1 + `branches` (one `if` each)."""
    body = "".join(f"    if (x == {i}) return {i};\n" for i in range(branches))
    return f"int {name}(int x) {{\n{body}    return -1;\n}}\n"


def write_fixture(directory, ccn):
    path = pathlib.Path(directory) / "fixture.cpp"
    path.write_text(branchy_function("simpleEnough", 3) + branchy_function("tooComplex", ccn - 1))
    return path


def test_fails_listing_the_function_above_the_limit(tmp_path, capsys):
    fixture = write_fixture(tmp_path, ccn=21)
    assert complexity_check.main(["--max-ccn", "20", str(tmp_path)]) == 1
    out = capsys.readouterr().out
    assert f"{fixture}:7: tooComplex has CCN 21 (limit 20)" in out
    assert "simpleEnough" not in out


def test_passes_at_the_limit(tmp_path, capsys):
    write_fixture(tmp_path, ccn=20)
    assert complexity_check.main(["--max-ccn", "20", str(tmp_path)]) == 0
    assert "no function above CCN 20" in capsys.readouterr().out


def test_default_limit_is_twenty(tmp_path):
    write_fixture(tmp_path, ccn=21)
    assert complexity_check.main([str(tmp_path)]) == 1
