"""The example of docs/python.md runs as written and prints what it says."""
import os
import pathlib
import re
import subprocess
import sys

import metalfit

DOC = pathlib.Path(__file__).parent.parent.parent / "docs" / "python.md"


def test_the_documented_example_runs(tmp_path):
    blocks = re.findall(r"```python\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)
    assert len(blocks) == 1
    env = dict(os.environ, PYTHONPATH=os.path.dirname(metalfit.__file__))  # this module, whatever the folder
    process = subprocess.run([sys.executable, "-c", blocks[0]], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert process.returncode == 0, process.stderr
    lines = process.stdout.splitlines()
    assert len(lines) == 5, process.stdout
    assert lines[1] == "[ True  True  True]"
    assert lines[2] == "(5, 2, 3)"
    assert lines[3] == "['glsl/metalfit_au_f82_tint.glsl', 'glsl/metalfit_models.glsl', 'metalfit_export.json']"
    assert lines[4].startswith("unknown material 'unobtainium'") and lines[4].endswith(" 2")
    assert (tmp_path / "gold-export" / "metalfit_export.json").is_file()
