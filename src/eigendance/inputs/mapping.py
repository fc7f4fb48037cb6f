"""Mappings: a mapping file or document, checked, and the basis it dances on
(docs/design.md#inputs, docs/design.md#mapping-file).

A mapping records the basis it was made on (`BasisRecord`: k, construction, the samples asked
and placed; the page's saved mappings and `eigendance gallery`'s do). Every command that takes
a mapping solves that basis unless told otherwise (`basis_choice`), and then says in one line
how the dance will differ. A mapping without the record (from before it, or a rig's) takes the
default k (`defaults.DEFAULT_K`, the page's k then too) and the construction rule. Where one
basis serves several mappings (`serve`, a batch's model) it is the one they record
(`shared_choice`), and each mapping made on another says so in the same line.
"""

from __future__ import annotations

import os
from dataclasses import dataclass

from eigendance.errors import InputError
from eigendance.files import read_json
from eigendance.harmonic.construction import BasisRecord
from eigendance.inputs.defaults import DEFAULT_K
from eigendance.music.mapping import Mapping

# The most values a mapping's lists may hold (a document sent to the server is checked for them
# before each value is): the bands of a spectrogram (`eigendance spectrum --bands`) and the
# harmonics of a basis (-k) at most, so that breeding answers a bounded size.
MAX_BANDS, MAX_HARMONICS = 1024, 20000


def check_mapping_size(data, name: str) -> None:
    """InputError unless a mapping document's lists (transfer, amplification, the palette's,
    the envelope's) fit MAX_BANDS and MAX_HARMONICS (checked before `Mapping.from_json` looks at
    every value).

    Parameters
    ----------
    data : the document as given (anything: `Mapping.from_json` says what else is wrong).
    name : how the message calls it.

    Raises
    ------
    InputError
        Naming the list that is too long.
    """
    if not isinstance(data, dict):
        return  # Mapping.from_json says what is wrong
    modes = data.get("modes") if isinstance(data.get("modes"), dict) else {}
    envelope = data.get("envelope") if isinstance(data.get("envelope"), dict) else {}
    for field_name, values, most in (
            ("transfer", data.get("transfer"), MAX_BANDS),
            ("amplification", data.get("amplification"), MAX_HARMONICS),
            *((f"modes.{key}", modes.get(key), MAX_HARMONICS)
              for key in ("selected", "amplitudes", "phases")),
            *((f"envelope.{key}", envelope.get(key), MAX_BANDS)
              for key in ("attack", "release", "threshold"))):
        if isinstance(values, list) and len(values) > most:
            raise InputError(f"{name}: {field_name} has {len(values)} values; at most "
                             f"{most}")


def mapping_from(data, name: str) -> Mapping:
    """A mapping from its parsed document: its size (`check_mapping_size`), then every field
    (`Mapping.from_json`).

    Parameters
    ----------
    data : the parsed document.
    name : how messages call it.

    Returns
    -------
    Mapping.

    Raises
    ------
    InputError
        Naming the field at fault.
    """
    check_mapping_size(data, name)
    return Mapping.from_json(data, name)


def read_mapping(path: str | os.PathLike) -> Mapping:
    """A mapping file (any readable version), checked.

    Parameters
    ----------
    path : a mapping JSON file.

    Returns
    -------
    Mapping.

    Raises
    ------
    InputError
        For a missing or unreadable file, JSON that is not JSON, a field at fault.
    """
    name = os.path.basename(os.fspath(path))
    return mapping_from(read_json(path, name), name)


@dataclass(frozen=True)
class BasisChoice:
    """The basis a command solves for a mapping: k, the construction ("auto" for the rule)
    and the samples of a reduced one; `note`, when the command line asked for another basis
    than the mapping's, says how the dance differs.

    Parameters
    ----------
    k, construction, samples : as above.
    note : one line, or None.
    """

    k: int
    construction: str = "auto"
    samples: int | None = None
    note: str | None = None


def basis_choice(mapping: Mapping | None, k: int | None = None,
                 construction: str | None = None) -> BasisChoice:
    """The basis to dance a mapping on: the one it records, unless the command line asks for
    another k or construction (then `note` says so); without a record, the default k.

    Parameters
    ----------
    mapping : the mapping given, or None.
    k : the -k asked for, or None.
    construction : --exact / --reduced asked for, or None.

    Returns
    -------
    BasisChoice.

    Example
    -------
    >>> made = Mapping([0.5], [1.0], name="m.json", basis=BasisRecord(150))
    >>> basis_choice(made)
    BasisChoice(k=150, construction='exact', samples=None, note=None)
    >>> basis_choice(made, k=300).note.split("; ")
    ['m.json was made on k = 150 harmonics (exact)', 'on k = 300 harmonics (exact) the same \
bands drive other harmonics: the dance differs from the one it was made on']
    """
    record = None if mapping is None else mapping.basis
    if record is None:
        return BasisChoice(k or DEFAULT_K, construction or "auto")
    asked = BasisRecord(k or record.k, construction or record.construction)
    if (asked.k, asked.construction) == (record.k, record.construction):
        return BasisChoice(record.k, record.construction, record.samples)
    note = (f"{mapping.name} was made on {record.describe()}; on {asked.describe()} the same "
            "bands drive other harmonics: the dance differs from the one it was made on")
    return BasisChoice(asked.k, asked.construction, None, note)


def record_note(mapping: Mapping | None, record: BasisRecord) -> str | None:
    """What to say when a mapping dances on a basis (a basis file, or the one solved for it)
    that is not the one it records: another k or construction, other samples asked, or other
    samples placed (a field the mapping or the basis does not know is not compared).

    Parameters
    ----------
    mapping : the mapping, or None.
    record : the basis's record (`HarmonicBasis.record`).

    Returns
    -------
    One line, or None when the mapping records no basis or this one.
    """
    made = None if mapping is None else mapping.basis
    if made is None or ((made.k, made.construction) == (record.k, record.construction) and all(
            None in pair or pair[0] == pair[1] for pair in
            ((made.samples, record.samples), (made.placed, record.placed)))):
        return None
    return (f"{mapping.name} was made on {made.describe()}; the basis danced on has "
            f"{record.describe()}, and the dance differs from the one it was made on")


def shared_choice(mappings, k: int | None = None, construction: str | None = None
                  ) -> tuple[BasisChoice, list[str]]:
    """The one basis several mappings dance on where one basis serves them all (a library, a
    batch's model): each mapping's `basis_choice` with what is asked, which must agree — the
    k and construction asked for, else the ones they record, else `DEFAULT_K` and the rule.

    Parameters
    ----------
    mappings : the mappings.
    k : the k asked for (-k, a plan's `k`), or None.
    construction : the construction asked for (--exact / --reduced, a plan's
        `construction`), or None.

    Returns
    -------
    (BasisChoice without its note, notes): one line (`basis_choice`'s, or `record_note`'s for
    other samples asked: the first mapping's are followed) for each mapping made on another
    basis than the one chosen.

    Raises
    ------
    InputError
        When no k (construction) is asked for and the mappings record different ones.

    Example
    -------
    >>> made = [Mapping([0.5], [1.0], name="a.json", basis=BasisRecord(24, "exact")),
    ...         Mapping([0.5], [1.0], name="old.json")]
    >>> shared_choice(made)
    (BasisChoice(k=24, construction='exact', samples=None, note=None), [])
    >>> shared_choice(made, construction="reduced")[1][0].split("; ")[0]
    'a.json was made on k = 24 harmonics (exact)'
    """
    recorded = [mapping for mapping in mappings if mapping.basis is not None]
    for asked, what, field in ((k, "k", "k"), (construction, "constructions", "construction")):
        found = sorted({str(getattr(mapping.basis, field)) for mapping in recorded})
        if asked is None and len(found) > 1:
            raise InputError(f"the mappings were made on bases of different {what} "
                             f"({', '.join(found)}); set {field}",
                             remedy={"k": max(mapping.basis.k for mapping in recorded)}
                             if field == "k" else None)
    choices = [basis_choice(mapping, k, construction) for mapping in recorded] or \
        [basis_choice(None, k, construction)]
    first = choices[0]
    chosen = BasisRecord(first.k, first.construction, first.samples)  # the first's samples
    notes = [choice.note or record_note(mapping, chosen)
             for mapping, choice in zip(recorded, choices, strict=False)]
    return BasisChoice(first.k, first.construction, first.samples), [note for note in notes if note]
