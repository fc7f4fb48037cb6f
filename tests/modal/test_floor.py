"""The floor under a rig (docs/design.md#the-floor): at the palette's largest amplitudes the skin
stays above the rest pose's lowest point (less FLOOR_SLACK of the diagonal), read from the
skinned positions (`Rig.positions`), not from the floor's own arithmetic; the mode tiles'
amplitudes are made to be seen within their bounds."""

import math
import os

import numpy as np
import pytest

from eigendance.modal.floor import FLOOR_SLACK, TILE_MOTION, TILE_REACH, tile_amplitudes
from eigendance.modal.motion import mode_coefficients
from eigendance.modal.palette import mode_reach, resolve_palette, single_mode_amplitudes
from eigendance.modal.rig import Rig
from eigendance.modal.sample_rigs import load_rig
from eigendance.music.mapping import ModeSettings
from helpers import fixture_path

HORSE = "/work/shared/data/rigged/quaternius_Horse.glb"  # four hooves on the floor


@pytest.fixture(scope="module")
def animal():
    path = HORSE if os.path.exists(HORSE) else fixture_path("rigged", "Fox.glb")
    rig = Rig(load_rig(path), dtype=np.float64)
    vertices = rig.skeleton.vertices
    extent = vertices.max(axis=0) - vertices.min(axis=0)
    floor = vertices[:, 1].min() - FLOOR_SLACK * math.hypot(*extent)  # y up, as glTF
    return rig, floor, math.hypot(*extent)


def lowest(rig, coefficients) -> float:
    return float(rig.positions(coefficients)[..., 1].min())


def test_each_mode_alone_at_its_cap_touches_the_floor_and_no_further(animal):
    """A mode alone at the largest amplitude the palette lets it have: the skin's lowest point
    (either sign of the swing) is on the floor less the slack; 1% more goes below it."""
    rig, floor, diagonal = animal
    model = rig.model
    for mode in (0, 3, 7, model.n_modes - 1):
        palette = resolve_palette(model, ModeSettings(np.array([mode]), np.array([1e6])))
        mu = palette.amplitudes[0] / mode_reach(model)[mode]
        c = np.zeros((2, model.n_modes))
        c[:, mode] = [mu, -mu]
        assert lowest(rig, c) == pytest.approx(floor, abs=1e-6 * diagonal), mode
        assert lowest(rig, 1.01 * c) < floor - 1e-7 * diagonal, mode


def test_the_palette_at_its_largest_amplitudes_keeps_the_hooves_above_the_floor(animal):
    """Every default-selected mode asked for 3 rad: in any phases (every sign of each swing,
    and the dance itself over 20 s, music off) the skin stays above the floor."""
    rig, floor, diagonal = animal
    model = rig.model
    selected = rig.palette.selected
    settings = ModeSettings(selected, np.full(len(selected), 3.0))
    palette = resolve_palette(model, settings)
    mu = palette.amplitudes / mode_reach(model)[selected]
    signs = np.array(np.meshgrid(*[[-1, 1]] * len(selected))).reshape(len(selected), -1).T
    c = np.zeros((len(signs), model.n_modes))
    c[:, selected] = signs * mu
    worst = lowest(rig, c)
    assert worst >= floor - 1e-6 * diagonal
    assert worst < floor + 0.01 * diagonal  # the cap binds: it is the largest that holds
    full = np.zeros(model.n_modes)
    full[selected] = mu
    dance = mode_coefficients(model, np.arange(0, 20, 0.05), full, modes=selected,
                              phases=np.arange(model.n_modes, dtype=float))
    assert lowest(rig, dance) >= floor - 1e-6 * diagonal


def test_the_default_palette_stays_above_the_floor(animal):
    rig, floor, diagonal = animal
    model, palette = rig.model, rig.palette
    signs = np.array(np.meshgrid(*[[-1, 1]] * len(palette.selected))).reshape(
        len(palette.selected), -1).T
    c = np.zeros((len(signs), model.n_modes))
    c[:, palette.selected] = signs * palette.amplitudes / mode_reach(model)[palette.selected]
    assert lowest(rig, c) >= floor - 1e-6 * diagonal


def test_mode_tiles_move_visibly_within_their_bounds(animal):
    """Each tile's amplitude: at most 90° of reach and the floor's cap; at least the default
    rule's; and where neither bound binds, its largest skin displacement is 5% of the
    diagonal (measured on the skinned positions)."""
    rig, floor, diagonal = animal
    model, skin = rig.model, rig.skin
    natural = single_mode_amplitudes(model)
    tiles = tile_amplitudes(model, skin, natural)
    reach = mode_reach(model)
    assert np.all(tiles <= TILE_REACH + 1e-12)
    for mode in range(0, model.n_modes, 9):
        c = np.zeros(model.n_modes)
        c[mode] = tiles[mode] / reach[mode]
        moved = np.linalg.norm(rig.positions(c)[0] - skin.vertices, axis=1).max()
        bound = tiles[mode] >= TILE_REACH - 1e-9 or lowest(rig, -c) < floor + 1e-6 * diagonal \
            or lowest(rig, c) < floor + 1e-6 * diagonal
        if not bound:
            assert tiles[mode] >= natural[mode] - 1e-12
            assert moved >= TILE_MOTION * diagonal * (1 - 1e-6), mode
