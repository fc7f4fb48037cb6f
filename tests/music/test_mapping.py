import json

import numpy as np
import pytest

from eigendance.errors import EigendanceError
from eigendance.harmonic.basis import HarmonicBasis
from eigendance.music.gallery import direct_transfer, initial_indices, reversed_transfer
from eigendance.music.mapping import (
    Mapping,
    ModeSettings,
    filters,
    harmonic_indices,
    resample_amplification,
)
from eigendance.music.spectrogram import band_edges
from helpers import bumpy_sphere

EDGES = band_edges(64, 44100)


@pytest.fixture(scope="module")
def basis():
    return HarmonicBasis.from_mesh(bumpy_sphere(2), 40, cache=False)


def random_mapping(rng, bands=8, k=12, seed=None):
    return Mapping(rng.uniform(0, 1, bands), rng.normal(0, 1, k), seed)


def test_harmonic_indices_and_cell_centres():
    k = 10
    np.testing.assert_array_equal(harmonic_indices([0.0, 0.099, 0.1, 0.55, 1.0], k),
                                  [0, 0, 1, 5, 9])
    nu = np.arange(k)
    np.testing.assert_array_equal(harmonic_indices((nu + 0.5) / k, k), nu)


def test_resample_amplification_by_normalised_index():
    a = np.array([1.0, 2.0])
    np.testing.assert_array_equal(resample_amplification(a, 4), [1, 1, 2, 2])
    np.testing.assert_array_equal(resample_amplification(a, 2), a)
    np.testing.assert_array_equal(resample_amplification(np.arange(6.0), 3), [1, 3, 5])


def test_zero_amplification_gives_identity_filter(rng):
    mapping = Mapping(rng.uniform(0, 1, 8), np.zeros(5))
    phi = mapping.filter(rng.uniform(0, 1, (7, 8)), 12)
    assert phi.shape == (7, 12)
    np.testing.assert_array_equal(phi, 1.0)


def test_filters_match_scatter_add_reference(rng):
    k = 12
    mappings = [random_mapping(rng, k=k), random_mapping(rng, k=5), random_mapping(rng, k=k)]
    values = rng.uniform(0, 1, (4, 3, 8))  # any batch of frames
    phi = filters(mappings, values, k)
    assert phi.shape == (3, 4, 3, k)
    for s, mapping in enumerate(mappings):
        nu = np.minimum(k - 1, np.floor(mapping.transfer * k).astype(int))
        a = resample_amplification(mapping.amplification, k)
        for index in np.ndindex(values.shape[:-1]):
            sums = np.zeros(k)
            np.add.at(sums, nu, values[index])
            np.testing.assert_allclose(phi[(s, *index)], a * sums + 1, atol=1e-12)
        np.testing.assert_allclose(mapping.filter(values, k), phi[s])


def test_filter_rejects_band_mismatch(rng):
    with pytest.raises(EigendanceError, match="8 bands; the spectrogram has 6"):
        random_mapping(rng).filter(np.zeros(6), 10)


def test_initial_transfer_definition(basis):
    nu = initial_indices(basis.frequencies, EDGES)
    centres = np.sqrt(EDGES[:-1] * EDGES[1:])
    levels = np.sqrt(np.maximum(basis.eigenvalues, 0) / basis.eigenvalues[-1])
    for xi, f in enumerate(centres):  # the smallest ν with f_ξ/f_{B−1} ≤ √(λ_ν/λ_{k−1})
        ratio = f / centres[-1]
        expected = next(v for v in range(basis.k) if ratio <= levels[v] * (1 + 1e-12))
        assert nu[xi] == expected
    assert nu[-1] == basis.k - 1


def test_direct_transfer_non_decreasing_and_reversed_is_its_mirror(basis):
    k = basis.k
    t_ini = direct_transfer(basis.frequencies, EDGES)
    t_rev = reversed_transfer(basis.frequencies, EDGES)
    assert (np.diff(t_ini) >= 0).all()
    assert (t_ini > 0).all() and (t_ini < 1).all()
    np.testing.assert_allclose(t_rev, 1 - t_ini, atol=1e-15)
    nu = harmonic_indices(t_ini, k)
    np.testing.assert_array_equal(nu, initial_indices(basis.frequencies, EDGES))
    np.testing.assert_array_equal(harmonic_indices(t_rev, k), k - 1 - nu)


def test_json_round_trip(tmp_path, rng):
    mapping = random_mapping(rng, seed=42)
    mapping.save(tmp_path / "m.json")
    loaded = Mapping.load(tmp_path / "m.json")
    np.testing.assert_array_equal(loaded.transfer, mapping.transfer)
    np.testing.assert_array_equal(loaded.amplification, mapping.amplification)
    assert loaded.seed == 42
    data = json.loads((tmp_path / "m.json").read_text())
    assert data["format"] == "eigendance.mapping" and data["version"] == 3
    assert data["bands"] == 8
    assert Mapping.from_json({**data, "seed": None}).seed is None


def valid():
    return {"format": "eigendance.mapping", "version": 1, "bands": 2, "transfer": [0.1, 0.9],
            "amplification": [1.0, -2.0, 3], "seed": None}


@pytest.mark.parametrize("change, message", [
    ({"format": "other"}, "format must be"),
    ({"version": 4}, "version must be one of"),
    ({"version": True}, "version must be one of"),
    ({"bands": 0}, "bands must be a positive integer"),
    ({"bands": 3}, "transfer has 2 values; bands says 3"),
    ({"transfer": [0.1, 1.5]}, r"transfer\[1\] = 1.5 is outside \[0, 1\]"),
    ({"transfer": [0.1, -0.0001]}, r"transfer\[1\]"),
    ({"transfer": [0.1, "x"]}, r"transfer\[1\] must be a number, not 'x'"),
    ({"transfer": [0.1, float("nan")]}, r"transfer\[1\] is not finite"),
    ({"amplification": [1.0, float("inf")]}, r"amplification\[1\] is not finite"),
    ({"amplification": []}, "amplification must be a non-empty list"),
    ({"amplification": None}, "amplification must be a non-empty list"),
    ({"seed": 1.5}, "seed must be an integer or null"),
])
def test_validation_errors_name_the_field(tmp_path, change, message):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({**valid(), **change}))  # NaN and Infinity as JSON extensions
    with pytest.raises(EigendanceError, match=message) as caught:
        Mapping.load(path)
    assert "\n" not in str(caught.value) and str(caught.value).startswith("bad.json: ")


@pytest.mark.parametrize("text, message", [
    ("{\"format\": ", "malformed JSON at line 1"),
    ("[1, 2]", "must be a JSON object"),
    ("", "malformed JSON"),
])
def test_malformed_json_is_one_line_error(tmp_path, text, message):
    path = tmp_path / "bad.json"
    path.write_text(text)
    with pytest.raises(EigendanceError, match=message) as caught:
        Mapping.load(path)
    assert "\n" not in str(caught.value)


def test_missing_mapping_file(tmp_path):
    with pytest.raises(EigendanceError, match="no such file"):
        Mapping.load(tmp_path / "none.json")


def test_version_2_carries_what_the_player_applies(tmp_path):
    mapping = Mapping([0.2, 0.7], [1.0, -2.0], 3, gain=1.5, smoothing=0.25, offset=1.0,
                      modes=ModeSettings(np.array([0, 2]), np.array([0.3, 0.1]),
                                         np.array([0.0, 1.0]), 0.5),
                      deformed_normal_weight=0.4, shading="flat")
    mapping.save(tmp_path / "m.json")
    again = Mapping.load(tmp_path / "m.json")
    assert again.to_json() == mapping.to_json()
    assert again.to_json()["version"] == 3 and again.modes.selected.tolist() == [0, 2]
    assert (again.gain, again.smoothing, again.offset, again.shading) == (1.5, 0.25, 1.0, "flat")


def test_version_1_files_are_still_read_with_default_settings():
    old = {"format": "eigendance.mapping", "version": 1, "bands": 2, "transfer": [0.1, 0.9],
           "amplification": [3.0], "seed": None}
    mapping = Mapping.from_json(old)
    assert (mapping.gain, mapping.smoothing, mapping.offset, mapping.modes) == (1.0, 0.0, 0.0,
                                                                               None)
    assert mapping.deformed_normal_weight == 0.4 and mapping.shading == "smooth"
    assert mapping.materials is True  # a model with materials is drawn in them


def test_the_clay_switch_is_saved_in_the_look(tmp_path):
    mapping = Mapping([0.2, 0.7], [1.0, -2.0], materials=False)
    mapping.save(tmp_path / "clay.json")
    again = Mapping.load(tmp_path / "clay.json")
    assert again.to_json()["look"]["materials"] is False and again.materials is False
    written = mapping.to_json()
    del written["look"]["materials"]  # a version-2 file written before the switch existed
    assert Mapping.from_json(written).materials is True


def test_gain_scales_the_amplification_of_the_filter(rng):
    values = rng.uniform(0, 1, (5, 8))
    mapping = random_mapping(rng)
    louder = Mapping(mapping.transfer, mapping.amplification, gain=2.5)
    np.testing.assert_allclose(louder.filter(values, 12) - 1,
                               2.5 * (mapping.filter(values, 12) - 1))
    np.testing.assert_allclose(louder.filter(values, 12, offset=0.0) + 1,
                               louder.filter(values, 12))


@pytest.mark.parametrize("changes, message", [
    ({"gain": -1}, "gain must be from 0 to 1000000, not -1"),
    ({"smoothing": "slow"}, "smoothing must be a number, not 'slow'"),
    ({"look": {"shading": "toon"}}, "shading must be one of"),
    ({"look": {"deformed_normal_weight": 2}}, "deformed_normal_weight must be from 0 to 1, not 2"),
    ({"look": {"materials": "yes"}}, "look.materials must be true or false"),
    ({"modes": {"selected": [0, 0]}}, "lists a mode twice"),
    ({"modes": {"selected": [0, 1], "phases": [0.0]}}, "modes.phases has 1 values for 2"),
    ({"modes": {"time_scale": 0}}, "time_scale must be positive"),
    ({"version": 4}, "version must be one of"),
])
def test_version_2_fields_are_checked(changes, message):
    data = {"format": "eigendance.mapping", "version": 2, "bands": 2, "transfer": [0.1, 0.9],
            "amplification": [3.0], "seed": None, **changes}
    with pytest.raises(EigendanceError, match=message) as caught:
        Mapping.from_json(data, "m.json")
    assert str(caught.value).startswith("m.json: ")
