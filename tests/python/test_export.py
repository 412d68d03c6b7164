"""export() writes the folder `metalfit export` writes, file for file, byte for byte."""
import metalfit
from conftest import run_cli


def folder_files(root):
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_export_equals_the_cli_export(tmp_path):
    module_dir, cli_dir = tmp_path / "module", tmp_path / "cli"
    written = metalfit.export(["Au", "Cu"], output=module_dir, models=["f82-tint", "schlick"],
                              formats=["json", "glsl", "mtlx"], roughness=0.25, jobs=1)
    run_cli("export", "Au,Cu", "--model", "f82-tint,schlick", "--format", "json,glsl,mtlx", "--roughness", "0.25",
            "-j", "1", "-o", str(cli_dir))
    module_files, cli_files = folder_files(module_dir), folder_files(cli_dir)
    assert module_files == cli_files
    assert written == sorted(module_files)
    assert "metalfit_export.json" in written
