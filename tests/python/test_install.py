"""The module installed with the CMake package: `cmake --install` into a prefix, the prefix moved, then imported
with PYTHONPATH=<prefix>/lib/python3/dist-packages and no $METALFIT_DATA: it finds the installed database."""
import json
import os
import shutil
import subprocess
import sys

import pytest

BUILD_DIR = os.environ.get("METALFIT_BUILD_DIR")


@pytest.mark.skipif(not BUILD_DIR, reason="METALFIT_BUILD_DIR (set by ctest) names the build to install")
def test_installed_module_finds_its_database(tmp_path):
    cmake = os.environ.get("CMAKE_COMMAND", "cmake")
    subprocess.run([cmake, "--install", BUILD_DIR, "--prefix", str(tmp_path / "prefix")], check=True,
                   capture_output=True)
    shutil.move(tmp_path / "prefix", tmp_path / "moved")
    site = tmp_path / "moved" / "lib" / "python3" / "dist-packages"
    assert (site / os.path.basename(__import__("metalfit").__file__)).is_file()
    env = {k: v for k, v in os.environ.items() if k not in ("METALFIT_DATA", "PYTHONPATH", "OCIO")}
    env["PYTHONPATH"] = str(site)
    script = ("import json, metalfit; "
              "print(json.dumps([metalfit.__file__, metalfit.data_dir(), "
              "metalfit.fit('Au', models='schlick', jobs=1)['provenance']['ocio_config']['file']]))")
    out = subprocess.run([sys.executable, "-c", script], env=env, cwd=tmp_path, check=True, capture_output=True,
                         text=True).stdout
    module_file, data_dir, ocio_file = json.loads(out)
    assert module_file.startswith(str(site))
    assert os.path.realpath(data_dir) == os.path.realpath(tmp_path / "moved" / "share" / "metalfit")
    assert ocio_file == "data:ocio/config.ocio"
