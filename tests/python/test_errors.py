"""Bad input raises metalfit's exceptions with the CLI's one-line message."""
import numpy as np
import pytest

import metalfit
from conftest import cli_error

FIXTURES = __import__("pathlib").Path(__file__).parent.parent / "fixtures"


def test_exception_types():
    assert issubclass(metalfit.Error, Exception)
    assert issubclass(metalfit.UsageError, metalfit.Error) and issubclass(metalfit.UsageError, ValueError)
    assert issubclass(metalfit.InputError, metalfit.Error)
    assert issubclass(metalfit.ColourConfigError, metalfit.Error)
    assert (metalfit.UsageError.exit_code, metalfit.InputError.exit_code, metalfit.ColourConfigError.exit_code) == \
        (2, 3, 4)


@pytest.mark.parametrize("call,cli", [
    (lambda: metalfit.fit("unobtainium"), ["fit", "unobtainium"]),
    (lambda: metalfit.fit("Au", models=["f99"]), ["fit", "Au", "--model", "f99"]),
    (lambda: metalfit.fit("Au", models="schlick", pin="F82"), ["fit", "Au", "--model", "schlick", "--pin", "F82"]),
    (lambda: metalfit.fit("Au", models="schlick", pin="F0", gamut_fit=True),
     ["fit", "Au", "--model", "schlick", "--pin", "F0", "--gamut-fit"]),
    (lambda: metalfit.fit("Au", models="schlick", illuminant="D1"), ["fit", "Au", "--model", "schlick",
                                                                       "--illuminant", "D1"]),
    (lambda: metalfit.fit("Au", models="schlick", space="no such space"),
     ["fit", "Au", "--model", "schlick", "--space", "no such space"]),
    (lambda: metalfit.fit(), ["fit"]),
    (lambda: metalfit.fit("Au", source="nobody"), ["fit", "Au", "--source", "nobody"]),
    (lambda: metalfit.reference("unobtainium"), ["show", "unobtainium"]),
    (lambda: metalfit.export("Au", output="/tmp/never", models="schlick", formats="docx"),
     ["export", "Au", "--model", "schlick", "--format", "docx", "-o", "/tmp/never"]),
    (lambda: metalfit.export("Au", output="/tmp/never", models="schlick", formats="glsl", roughness=2),
     ["export", "Au", "--model", "schlick", "--format", "glsl", "--roughness", "2", "-o", "/tmp/never"]),
])
def test_usage_errors_carry_the_cli_message(call, cli):
    code, message = cli_error(*cli)
    with pytest.raises(metalfit.Error) as raised:
        call()
    assert str(raised.value) == message
    assert type(raised.value).exit_code == code


@pytest.mark.parametrize("fixture", ["bad-negative-k.csv", "bad-non-numeric.yml", "bad-unit.tsv", "bad-row.csv"])
def test_bad_files_raise_input_error_with_the_cli_message(fixture):
    path = str(FIXTURES / fixture)
    code, message = cli_error("fit", path, "--model", "schlick")
    assert code == 3
    with pytest.raises(metalfit.InputError) as raised:
        metalfit.fit(path, models="schlick")
    assert str(raised.value) == message
    with pytest.raises(metalfit.InputError) as raised:
        metalfit.reference(path)
    assert str(raised.value) == cli_error("show", path)[1]


def test_bad_python_arguments_raise_value_error():
    with pytest.raises(ValueError, match=r"params must have shape \(\.\.\., 2, 3\)"):
        metalfit.evaluate("f82-tint", np.ones((3, 3)), 0.5)
    with pytest.raises(ValueError, match="lacks 'tint'"):
        metalfit.evaluate("f82-tint", {"F0": [1, 1, 1]}, 0.5)
    with pytest.raises(ValueError):  # NumPy's message: shapes that do not broadcast
        metalfit.evaluate("schlick", np.ones((4, 1, 3)), np.ones(5))
    with pytest.raises(metalfit.UsageError, match="unknown model"):
        metalfit.evaluate("no-such-model", np.ones((1, 3)), 0.5)
    with pytest.raises(metalfit.UsageError, match="mu must be in"):
        metalfit.reference("Au", mu=[0.5, 1.5])
    with pytest.raises(metalfit.UsageError, match="--nodes"):
        metalfit.fit("Au", nodes=1)
