"""catalog(), fit() and reference() give what the CLI's JSON gives, exactly."""
import numpy as np
import pytest

import metalfit
from conftest import cli_json


def test_catalog_equals_list_json():
    catalog = metalfit.catalog()
    assert catalog == cli_json("list", "--json")
    assert any(entry["id"] == "Au" for entry in catalog)


def test_fit_record_equals_fit_json(gold_fit):
    record, cli = gold_fit
    assert record == cli  # every key, every number (shortest round-trip text both ways)
    assert list(record["materials"]["Au"]["models"]) == ["f82-tint", "schlick"]


@pytest.mark.parametrize("options,cli_options", [
    (dict(space="ACEScg", convention="adobe", pin="F0"), ["--space", "ACEScg", "--convention", "adobe", "--pin", "F0"]),
    (dict(metric="abs", weight="cosine", nodes=32, cmf="1964", illuminant="D50"),
     ["--metric", "abs", "--weight", "cosine", "--nodes", "32", "--cmf", "1964", "--illuminant", "D50"]),
    (dict(gamut_fit=True, budget="1%", source="McPeak"), ["--gamut-fit", "--budget", "1%", "--source", "McPeak"]),
])
def test_fit_options_mean_the_cli_options(options, cli_options):
    record = metalfit.fit("Cu", models="f82-tint,schlick", jobs=1, **options)
    assert record == cli_json("fit", "Cu", "--model", "f82-tint,schlick", "-j", "1", "--json", *cli_options)


def test_fit_of_several_materials_and_a_file(tmp_path):
    fixture = str(__import__("pathlib").Path(__file__).parent.parent / "fixtures" / "valid-nk.csv")
    record = metalfit.fit(["Ag", fixture], models=["schlick"], jobs=2)
    assert record == cli_json("fit", "Ag", fixture, "--model", "schlick", "--json")


def test_reference_equals_show_json():
    show = cli_json("show", "Cu", "--space", "ACEScg", "--convention", "adobe", "--json")
    mu_f82 = 1.0 / 7.0  # libfit's kMuF82 (F82: mu = 1/7, about cos 82 degrees)
    expected = [show["F0"], show["F82"], show["R"]["0.5"], show["R"]["0.25"], show["R"]["0.1"]]
    curve = metalfit.reference("Cu", mu=[1.0, mu_f82, 0.5, 0.25, 0.1], space="ACEScg", convention="adobe")
    assert curve.shape == (5, 3)
    for row, rgb in zip(curve, expected):
        assert row.tolist() == pytest.approx(rgb, abs=1e-12, rel=0)


def test_reference_shapes():
    assert metalfit.reference("Au").shape == (101, 3)  # default: 101 mu from 0 to 1
    assert metalfit.reference("Au", mu=0.5).shape == (3,)
    grid = metalfit.reference("Au", mu=np.linspace(0, 1, 6).reshape(2, 3))
    assert grid.shape == (2, 3, 3)
    assert np.array_equal(grid.reshape(6, 3), metalfit.reference("Au", mu=np.linspace(0, 1, 6)))
    assert np.allclose(metalfit.reference("Au", mu=[0.0])[0], 1.0, atol=1e-12)  # R_c(0) = 1 (white balance)
