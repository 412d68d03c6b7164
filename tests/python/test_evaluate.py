"""evaluate(): the models at NumPy arrays of mu and parameters, broadcast like NumPy's own operations."""
import numpy as np
import pytest

import metalfit


def fitted(record, material, model):
    return record["materials"][material]["models"][model]["fit"]


def test_evaluate_equals_itself_per_element_and_broadcasts(gold_fit):
    record, _ = gold_fit
    params = fitted(record, "Au", "f82-tint")["params"]
    p = np.stack([params["F0"], params["tint"]])  # shape (2, 3): the parameters' order of metalfit.models()
    mu = np.linspace(0.0, 1.0, 7)
    by_dict = metalfit.evaluate("f82-tint", params, mu)
    assert by_dict.shape == (7, 3)
    assert np.array_equal(by_dict, metalfit.evaluate("f82-tint", p, mu))
    # A scalar mu gives one RGB triple, the same as the row of the array.
    for i, m in enumerate(mu):
        one = metalfit.evaluate("f82-tint", p, float(m))
        assert one.shape == (3,)
        assert np.array_equal(one, by_dict[i])
    # mu of shape (n, 1) against a stack of m parameter sets: (n, m, 3), each element the single evaluation.
    stack = np.stack([p, p * 0.5, np.clip(p * 1.1, 0, 1)])  # (3, 2, 3)
    grid = metalfit.evaluate("f82-tint", stack, mu.reshape(-1, 1))
    assert grid.shape == (7, 3, 3)
    for i in range(7):
        for j in range(3):
            assert np.array_equal(grid[i, j], metalfit.evaluate("f82-tint", stack[j], mu[i]))
    # A scalar mu against the stack, and a dict of (m, 3) arrays.
    assert metalfit.evaluate("f82-tint", stack, 0.3).shape == (3, 3)
    as_dict = metalfit.evaluate("f82-tint", {"F0": stack[:, 0], "tint": stack[:, 1]}, mu.reshape(-1, 1))
    assert np.array_equal(as_dict, grid)


def test_evaluate_is_the_model_not_a_copy():
    # Schlick: F0 + (1 - F0) (1 - mu)^5, its definition.
    f0 = np.array([0.9, 0.6, 0.5])
    mu = np.array([0.0, 0.25, 1.0])
    expected = f0 + (1.0 - f0) * (1.0 - mu[:, None]) ** 5
    assert np.allclose(metalfit.evaluate("schlick", f0[None, :], mu), expected, rtol=1e-14, atol=1e-15)


@pytest.mark.parametrize("model", ["f82-tint", "schlick", "conductor-rgb"])
def test_evaluate_at_the_fit_matches_the_reference_within_the_reported_error(model):
    record = metalfit.fit("Au", models=[model], jobs=1)
    fit = fitted(record, "Au", model)
    # Gauss-Legendre nodes on [0, 1] and the weight of the record: the fit's rel_rms, per channel.
    nodes, weights = np.polynomial.legendre.leggauss(record["provenance"]["nodes"])
    mu = 0.5 * (nodes + 1.0)
    w = 0.5 * weights
    model_curve = metalfit.evaluate(model, fit["params"], mu)
    reference = metalfit.reference("Au", mu=mu)
    rel_rms = np.sqrt(np.sum(w[:, None] * ((model_curve - reference) / reference) ** 2, axis=0))
    assert rel_rms == pytest.approx(fit["metrics"]["rel_rms"], rel=1e-6, abs=1e-12)
    # And pointwise within the reported maximum relative error.
    dense = np.linspace(0.0, 1.0, 1025)
    rel = np.abs(metalfit.evaluate(model, fit["params"], dense) / metalfit.reference("Au", mu=dense) - 1.0)
    assert np.all(rel.max(axis=0) <= np.array(fit["metrics"]["max_rel"]) * (1 + 1e-9) + 1e-12)


def test_models_lists_the_registry():
    models = metalfit.models()
    assert [m["id"] for m in models][:1] and all(m["parameters"] for m in models)
    assert {"id": "schlick", "title": models[[m["id"] for m in models].index("schlick")]["title"],
            "parameters": ["F0"]} in models
