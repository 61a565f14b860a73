r"""Robustness of a verdict to chance and to combinations of assumed inputs.

A row whose value rests on inputs the document does not give (``depends_on``, each with
a plausible range, ``<doc>.plausible`` in ``config.yaml``) or on a Monte Carlo result is
judged at more points than its nominal one (issue 21 item 5, ``shared/CONTRACTS.md``
section 3, column ``robust``). Three designs, one rule: ``robust=true`` only when the
verdict is the same at every point of every design that applies to the row (for a Monte
Carlo row: at every point where the inputs, not chance, decide it, and under chance at
the declared share; see ``chance`` below); otherwise ``robust=false``, the verdict is
``not_reproducible`` and the note says where each verdict holds.

``one_at_a_time``
    each input over its plausible grid, the others nominal
    (:func:`abglib.replications.evaluate`).
``joint``
    one design for the whole document (:func:`joint_design`), over the inputs its rows
    depend on:

    * *corners*: for every row with ``2 <= k <= corner_inputs`` inputs, every
      combination of the ends of its ranges (:func:`ends`: low and high of a numeric
      range, every value of a categorical one, so ``2**k`` corners when the categorical
      ranges have two values). The corners of all such rows are packed into few points
      by a greedy covering (:func:`corner_design`); an input no packed corner needs
      stays nominal;
    * *space-filling*: when some row has ``k > corner_inputs`` inputs, ``joint_points``
      points of a Latin hypercube (:class:`scipy.stats.qmc.LatinHypercube`, seeded with
      ``design_seed``) over the union of those rows' inputs (:func:`latin_hypercube`).
      The hypercube's coordinate ``u`` in [0, 1) of an input whose plausible grid has
      ``m`` values picks ``values[floor(u m)]``: every point lies on the declared grids,
      and each input's ``m`` values are visited in equal shares (a Latin hypercube is
      stratified in every coordinate).

    A joint point moves several inputs at once; a row is judged at the point's
    *projection* onto its own inputs (:func:`project`), since ``depends_on`` declares
    that no other input changes its value (a row whose verdict changed with an
    undeclared input would show the change as a flip at that point). A projection that
    moves at most one input is a point of the one-at-a-time sweep and is not repeated.
Every point off the nominal inputs, one at a time or joint, is drawn with one of the seed
sets below in turn (:func:`point_seed_sets`), so that a Monte Carlo row meets a fresh
draw at each of them: a verdict that holds only for the configured draw away from the
nominal inputs is found as well. A Monte Carlo row is judged at each joint point under
``joint_seed_sets`` seed sets (:func:`draws_of_point`: the point's own set and the next
ones in turn); a row that reads no seeded draw keeps one (its result is the same under
every set). One draw per joint point was too few: with one, an Al-Wagih row (Table 2, X,
'M5 gives very lower RMSE') was ``robust=true`` under the configured seeds and flipped
when every seed was shifted by 104729.

``chance``
    How a Monte Carlo row's draws make one verdict. A draw's verdict is a random
    outcome: under "every draw agrees" (v0.4.0), rows contradicted at a few per cent of
    the draws were robust in one rebuild and fragile in the next (measured with every
    seed shifted by 104729, 7919 and 1299709: 1, 7 and 5 Al-Wagih rows marked
    ``robust=true`` flipped, and no number of draws per joint point up to 4 stopped it).
    Two rules replace it (v0.4.1):

    * *a flip by the inputs is confirmed*: at a design point whose scheduled draws
      contradict the nominal verdict, the row gets more draws there, up to
      ``confirm_draws`` (:func:`confirmation_draws`); the point flips the verdict only
      when every draw contradicts it with the same other verdict (:func:`point_verdict`).
      A point where the inputs change the verdict outright is found always; chance
      alone fakes one with probability ``p**confirm_draws`` for a per-draw rate ``p``.
    * *chance is a rate, bounded*: the row's scheduled draws (the configured seeds,
      every seed set at the nominal inputs, the scheduled draws of every design point
      that is not a flip) estimate the rate at which chance contradicts the nominal
      verdict over that mixture of points. The verdict is robust to chance when the
      one-sided ``chance_confidence`` (99 %) Clopper-Pearson upper bound on that rate is
      at most ``chance_tolerance`` (10 %: nine realisations in ten reproduce it), fragile
      when the lower bound is above it; while undecided, the row gets one more draw at a
      time, at its nominal inputs and each of its design points that is not a flip in
      turn, with seed sets beyond the design's (:func:`extra_draws`), up to
      ``chance_draws`` (500) draws in all, and is fragile if still undecided there
      (:func:`chance_judgement`). The note gives the draws and the bound whenever a draw
      contradicts.

    What the label so guarantees is computed, not assumed (:func:`robust_probability`,
    exact, checked against a simulation): the row is looked at after every draw, so the
    per-look 99 % is spent many times over; over the whole sequence a row contradicted
    at the tolerance ends robust in at most about 6 % of rebuilds, whatever its number of
    scheduled draws, at 12 % in about 1 %, and a row at 5 % ends robust in at least 98 %.
    Between about 6 % and 9 % lies a band where the label is decided by the draws (50 %
    near 7.5 %): a row whose rate lies there can be robust in one rebuild and fragile in
    the next, and no finite number of draws removes the band, only narrows it.

    History (every figure measured with all seeds shifted by 104729, 7919 and 1299709,
    ``tools/seed-shift.py``): "every draw agrees" (v0.4.0) flipped 1, 7 and 5 Al-Wagih
    rows marked ``robust=true``. A share against 10 % then flipped Huang's Figs 6-7
    conclusion (40 of 42 draws agree under the configured seeds, 35 of 42 with 7919).
    v0.4.1's bound (95 % a look, 150 draws, extras at the nominal inputs, and no
    contradiction at all counted as robust) flipped one Al-Wagih row under 1299709
    (Table 4, M1 vs M3, Y: 1 % contradicted at its nominal inputs, about a quarter at
    the joint points with ``m1_alpha = 0.01``, robust by a hair at 134 of 142) and,
    once the extras went over the whole mixture, Huang's Figs 6-7 conclusion (85 of 89,
    bound 9.99 %, then undecided at 150 under 7919 and 1299709). Its robust label was
    also weaker than it read: a row at 10 % was robust in 13 % of rebuilds with 46
    scheduled draws and in 59 % with 6, since 6 agreeing draws counted as robust
    (``0.9**6 = 53 %``). v0.4.2's rule is the one above.

    ``robust=true`` so means: the verdict holds at every point of every design, and
    chance contradicts it in fewer than one draw in ten, by a sequential bound whose
    error over the whole sequence is known.

``seed_set``
    the document's config with every random seed it reads moved together
    (:func:`seed_sets`): keys named ``seed`` or ending in ``_seed`` (integers) in the
    document's own section and in the ``datasets`` section, set ``k`` (``k = 1 ..
    seed_sets``) adding ``k * seed_prime`` to each. ``seed_prime`` is a large prime
    (default 1 000 003): far larger than the offsets a document adds to one configured
    seed (``seed + i`` for the i-th run, cell or row, a few hundred at most), so no two
    sets share a draw (checked: :data:`SEED_GAP`); numpy's ``SeedSequence`` makes
    distinct seeds independent streams. A row *rests on a Monte Carlo result* when its
    result (value, note, readings) under set 1 differs from the configured one
    (:func:`rests_on_chance`): detected, never listed by hand. Such a row is judged
    under every set; a row whose result is bit-identical under set 1 reads no seeded
    draw, and is judged under no further set.

The design's sizes are declared in ``config.yaml``, section ``robustness``
(:data:`DEFAULTS`, checked by :func:`settings`), with a schema entry in
``workflow/schemas/config.schema.yaml``.

This module imports the core and numpy/scipy only (the layering of
:mod:`abglib.verdicts`).
"""

from __future__ import annotations

import copy
import functools
import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from .._checks import AbglibValueError
from ._numbers import format_number

__all__ = [
    "DEFAULTS",
    "DESIGNS",
    "MIN_SEED_SETS",
    "ROBUSTNESS_COLUMNS",
    "SEED_GAP",
    "Design",
    "JointPoint",
    "ChanceJudgement",
    "chance_judgement",
    "seed_set",
    "confirmation_draws",
    "corner_design",
    "describe_joint",
    "describe_seed_sets",
    "draws_of_point",
    "ends",
    "joint_design",
    "latin_hypercube",
    "point_seed_sets",
    "point_verdict",
    "project",
    "rests_on_chance",
    "seed_paths",
    "seed_sets",
    "settings",
    "with_seeds_shifted",
    "with_values",
    "config_get",
]

#: Columns of ``results/<doc>/robustness.csv``: one row per judged point. ``design`` is
#: one of :data:`DESIGNS`. ``input``/``value``: the input and its value (one at a time);
#: the moved inputs and their values, ``;``-separated and aligned (joint); ``seeds`` and
#: the set ``k`` (seed set; ``k = 0`` the configured seeds). ``seed_set`` is the seed set
#: the point was drawn with (:func:`point_seed_sets`; 0: the configured seeds); a Monte
#: Carlo row has one joint row per seed set of the point (:func:`draws_of_point`).
#: ``nominal`` is true at the configured point.
ROBUSTNESS_COLUMNS = [
    "key",
    "design",
    "input",
    "value",
    "seed_set",
    "nominal",
    "reproduced",
    "verdict",
]

#: The designs of a robustness row, in the order they are judged.
DESIGNS = ("one_at_a_time", "joint", "seed_set")

#: The fewest seed sets besides the configured one (CONTRACTS.md section 3, from v0.4.0).
MIN_SEED_SETS = 5

#: Two seeds of different seed sets must differ by at least this much: a document draws
#: with ``seed + i`` for i below its number of runs, cells or rows (500 at most in
#: ``config.yaml``), so sets closer than this could share a stream.
SEED_GAP = 10_000

#: The design of ``config.yaml``'s ``robustness`` section when a key is absent (the
#: schema's defaults).
DEFAULTS = {
    "seed_sets": 5,
    "seed_prime": 1_000_003,
    "joint_seed_sets": 2,
    "corner_inputs": 3,
    "joint_points": 8,
    "design_seed": 20_261_201,
    "confirm_draws": 3,
    "chance_tolerance": 0.1,
    "chance_confidence": 0.99,
    "chance_draws": 500,
}

# allowed ranges of the keys (the schema's; the message names them)
_LIMITS = {
    "seed_sets": (MIN_SEED_SETS, 50),
    "seed_prime": (100_003, 2**31 - 1),
    "joint_seed_sets": (1, 50),
    "corner_inputs": (1, 8),
    "joint_points": (4, 256),
    "design_seed": (0, 2**32 - 1),
    "confirm_draws": (1, 50),
    "chance_tolerance": (0.0, 0.5),
    "chance_confidence": (0.5, 1.0),
    "chance_draws": (10, 1000),
}

# the keys that are shares (floats in [lo, hi)), not counts
_SHARES = ("chance_tolerance", "chance_confidence")

# the sections whose seeds a seed set moves (besides the document's own)
_SEED_SECTIONS = ("datasets",)

#: Above this many combinations of the ends of the inputs, corners are packed first-fit
#: (:func:`corner_design`) instead of by the greedy search over every combination.
_MAX_CANDIDATES = 1 << 16


class Axis(Protocol):
    """What the designs need of a plausible range
    (:class:`abglib.replications.PlausibleRange` is one)."""

    name: str
    nominal: Any
    values: tuple
    numeric: bool


@dataclass(frozen=True)
class Design:
    """The sizes of the robustness designs (``config.yaml`` section ``robustness``).

    Attributes
    ----------
    seed_sets : int
        Seed sets besides the configured one (at least :data:`MIN_SEED_SETS`).
    seed_prime : int
        Set ``k`` moves every seed by ``k * seed_prime`` (a prime).
    joint_seed_sets : int
        Seed sets a Monte Carlo row is judged under at each joint point (at most
        ``seed_sets``; :func:`draws_of_point`).
    corner_inputs : int
        Rows with at most this many inputs are judged at every corner of their ranges;
        rows with more, over the Latin hypercube.
    joint_points : int
        Points of the Latin hypercube.
    design_seed : int
        Seed of the Latin hypercube (the design is fixed by the config).
    confirm_draws : int
        Draws a Monte Carlo row gets at a design point whose first draws contradict its
        nominal verdict (:func:`confirmation_draws`); the point counts as a flip by the
        inputs only when all of them contradict it (:func:`point_verdict`).
    chance_tolerance : float
        The largest share of a Monte Carlo row's scheduled draws that may contradict its
        nominal verdict for the verdict to count as robust to chance
        (:func:`chance_judgement`).
    chance_confidence : float
        One-sided confidence of the Clopper-Pearson bounds on the contradiction rate, at
        each look (the row is looked at after every draw: :func:`robust_probability`
        gives what the whole sequence guarantees).
    chance_draws : int
        The most draws a Monte Carlo row whose verdict under chance is undecided is
        judged over (more draws over its mixture of points, :func:`extra_draws`).
    """

    seed_sets: int = DEFAULTS["seed_sets"]
    seed_prime: int = DEFAULTS["seed_prime"]
    joint_seed_sets: int = DEFAULTS["joint_seed_sets"]
    corner_inputs: int = DEFAULTS["corner_inputs"]
    joint_points: int = DEFAULTS["joint_points"]
    design_seed: int = DEFAULTS["design_seed"]
    confirm_draws: int = DEFAULTS["confirm_draws"]
    chance_tolerance: float = DEFAULTS["chance_tolerance"]
    chance_confidence: float = DEFAULTS["chance_confidence"]
    chance_draws: int = DEFAULTS["chance_draws"]


def settings(config: Mapping) -> Design:
    """The robustness design declared in ``config['robustness']`` (defaults:
    :data:`DEFAULTS`).

    Raises
    ------
    AbglibValueError
        An unknown key, a value that is not an integer, outside its allowed range (e.g.
        fewer than :data:`MIN_SEED_SETS` seed sets, or more ``joint_seed_sets`` than
        ``seed_sets``), or a ``seed_prime`` that is not prime; the message names the
        key, the allowed range and the value.
    """
    spec = config.get("robustness", None) or {}
    if not isinstance(spec, Mapping):
        raise AbglibValueError(f"robustness must be a mapping, got {spec!r}")
    unknown = sorted(set(spec) - set(DEFAULTS))
    if unknown:
        raise AbglibValueError(
            f"robustness: unknown keys {unknown}; allowed keys are {sorted(DEFAULTS)}"
        )
    out = {}
    for key, default in DEFAULTS.items():
        value = spec.get(key, default)
        lo, hi = _LIMITS[key]
        name = f"robustness.{key}"
        if key in _SHARES:
            ok = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(
                value, bool
            )
            if not ok or not lo <= float(value) < hi:
                raise AbglibValueError(f"{name} must satisfy {lo} <= {name} < {hi}, got {value!r}")
            out[key] = float(value)
            continue
        if not isinstance(value, (int, np.integer)) or isinstance(value, bool):
            raise AbglibValueError(f"{name} must be an integer in [{lo}, {hi}], got {value!r}")
        if not lo <= int(value) <= hi:
            raise AbglibValueError(f"{name} must satisfy {lo} <= {name} <= {hi}, got {value!r}")
        out[key] = int(value)
    if out["joint_seed_sets"] > out["seed_sets"]:
        raise AbglibValueError(
            f"robustness.joint_seed_sets must satisfy 1 <= robustness.joint_seed_sets <= "
            f"robustness.seed_sets = {out['seed_sets']}, got {out['joint_seed_sets']}"
        )
    if out["confirm_draws"] > out["seed_sets"]:
        raise AbglibValueError(
            f"robustness.confirm_draws must satisfy 1 <= robustness.confirm_draws <= "
            f"robustness.seed_sets = {out['seed_sets']}, got {out['confirm_draws']}"
        )
    if not _is_prime(out["seed_prime"]):
        raise AbglibValueError(
            f"robustness.seed_prime must be a prime, got {out['seed_prime']} "
            f"(= {_smallest_factor(out['seed_prime'])} x "
            f"{out['seed_prime'] // _smallest_factor(out['seed_prime'])})"
        )
    return Design(**out)


def _smallest_factor(n: int) -> int:
    if n % 2 == 0:
        return 2
    for f in range(3, math.isqrt(n) + 1, 2):
        if n % f == 0:
            return f
    return n


def _is_prime(n: int) -> bool:
    return n >= 2 and _smallest_factor(n) == n


# --------------------------------------------------------------------------- config paths
def config_get(config: Mapping, path: str):
    """The value at a dotted path (``'huang.radar.tau_s'``) of a nested mapping (a list
    is indexed by a number: ``'datasets.scenarios.0.seed'``).

    Raises
    ------
    AbglibValueError
        Naming the path and the part that is missing.
    """
    node = config
    for part in path.split("."):
        if isinstance(node, Mapping) and part in node:
            node = node[part]
        elif isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            raise AbglibValueError(f"config has no entry {path!r} (missing {part!r})")
    return node


#: Leaves a config copy shares: immutable, so ``copy.copy`` would return them unchanged.
_IMMUTABLE = frozenset({str, int, float, bool, type(None)})


def _plain(x):
    if type(x) in _IMMUTABLE:
        return x
    if isinstance(x, Mapping):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    return copy.copy(x)


def with_values(config: Mapping, values: Mapping[str, Any]) -> dict:
    """A deep copy of ``config`` with every dotted path of ``values`` set (each path must
    exist: a typo must not create a key)."""
    for path in values:
        config_get(config, path)
    out = _plain(config)
    for path, value in values.items():
        parts = path.split(".")
        node = out
        for part in parts[:-1]:
            node = node[int(part)] if isinstance(node, list) else node[part]
        if isinstance(node, list):
            node[int(parts[-1])] = copy.deepcopy(value)
        else:
            node[parts[-1]] = copy.deepcopy(value)
    return out


# --------------------------------------------------------------------------- seed sets
def _is_seed_key(key) -> bool:
    return isinstance(key, str) and (key == "seed" or key.endswith("_seed"))


def seed_paths(config: Mapping, doc: str) -> dict[str, int]:
    """Every random seed the document's study reads: ``{dotted path: seed}`` for the keys
    named ``seed`` or ending in ``_seed`` in ``config[doc]`` and ``config['datasets']``.

    Raises
    ------
    AbglibValueError
        A seed key whose value is not a non-negative integer.
    """
    found: dict[str, int] = {}

    def walk(node, prefix):
        if isinstance(node, Mapping):
            for k, v in node.items():
                path = f"{prefix}.{k}"
                if _is_seed_key(k) and not isinstance(v, (Mapping, list)):
                    if v is None:
                        continue
                    if not isinstance(v, (int, np.integer)) or isinstance(v, bool) or v < 0:
                        raise AbglibValueError(
                            f"{path} must be a non-negative integer seed, got {v!r}"
                        )
                    found[path] = int(v)
                else:
                    walk(v, path)
        elif isinstance(node, list):
            for i, v in enumerate(node):
                walk(v, f"{prefix}.{i}")

    for section in (doc, *_SEED_SECTIONS):
        if section in config:
            walk(config[section], section)
    return found


def with_seeds_shifted(config: Mapping, doc: str, shift: int) -> dict:
    """``config`` with every seed of :func:`seed_paths` moved by ``shift``."""
    return with_values(config, {p: s + int(shift) for p, s in seed_paths(config, doc).items()})


def seed_sets(config: Mapping, doc: str, design: Design | None = None) -> list[dict]:
    """The configs of seed sets ``k = 1 .. design.seed_sets``: every seed moved by
    ``k * design.seed_prime``. Empty when the document reads no seed.

    Raises
    ------
    AbglibValueError
        When two seeds of different sets (the configured one included) are closer than
        :data:`SEED_GAP`, naming them.
    """
    design = design or settings(config)
    seeds = seed_paths(config, doc)
    if not seeds:
        return []
    p, n = design.seed_prime, design.seed_sets
    drawn = sorted((s + k * p, k, path) for k in range(n + 1) for path, s in seeds.items())
    for (a, ka, pa), (b, kb, pb) in zip(drawn, drawn[1:], strict=False):
        if ka != kb and b - a < SEED_GAP:
            raise AbglibValueError(
                f"{doc}: seed sets {ka} and {kb} come within {b - a} of each other "
                f"({pa} = {a}, {pb} = {b}); two sets must stay {SEED_GAP} apart: choose "
                f"another robustness.seed_prime (now {p})"
            )
    return [with_seeds_shifted(config, doc, k * p) for k in range(1, n + 1)]


def rests_on_chance(nominal, other) -> bool:
    """Whether a claim's result changed under another seed set: its value, note or
    readings differ (NaN equals NaN). ``nominal`` and ``other`` carry ``value``,
    ``note`` and ``readings`` (:class:`abglib.replications.Result`)."""
    if not _same_value(nominal.value, other.value) or nominal.note != other.note:
        return True
    a, b = tuple(nominal.readings), tuple(other.readings)
    if len(a) != len(b):
        return True
    return any(
        ra.description != rb.description or not _same_value(ra.value, rb.value)
        for ra, rb in zip(a, b, strict=True)
    )


def _same_value(a, b) -> bool:
    if _is_number(a) and _is_number(b):
        fa, fb = float(a), float(b)
        return fa == fb or (math.isnan(fa) and math.isnan(fb))
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return bool(np.array_equal(np.asarray(a), np.asarray(b), equal_nan=True))
    return type(a) is type(b) and a == b


def _is_number(v) -> bool:
    return isinstance(v, (int, float, np.integer, np.floating)) and not isinstance(
        v, (bool, np.bool_)
    )


# --------------------------------------------------------------------------- joint design
@dataclass(frozen=True)
class JointPoint:
    """One point of a document's joint design.

    ``kind`` is ``corner`` or ``hypercube``, ``index`` its number within its kind
    (from 1), ``values`` the inputs it moves off their nominal values
    (``{dotted path: value}``; every other input nominal).
    """

    kind: str
    index: int
    values: Mapping[str, Any]

    @property
    def label(self) -> str:
        return f"{self.kind} {self.index}"


def ends(axis: Axis) -> tuple:
    """The ends of a plausible range: its lowest and highest value when numeric, every
    value when categorical (in the declared order)."""
    if axis.numeric:
        return (min(axis.values), max(axis.values))
    return tuple(axis.values)


def _same(a, b) -> bool:
    if _is_number(a) and _is_number(b):
        return math.isclose(float(a), float(b), rel_tol=1e-12, abs_tol=0.0) or a == b
    return a == b


def _key(v):
    # a value as a dictionary key (a list-valued input, e.g. a diagonal, by its repr)
    return repr(v) if isinstance(v, (list, dict)) else v


def corner_design(
    axes: Mapping[str, Axis], input_sets: Iterable[Sequence[str]], max_inputs: int
) -> list[dict[str, Any]]:
    """Points that together hold every corner of every input set of ``2 .. max_inputs``
    inputs.

    A corner of an input set assigns one of its :func:`ends` to each input. The corners
    of all sets are packed greedily: the candidates are the combinations of the ends of
    every input involved (in lexicographic order of the ends); each point is the first
    candidate that holds the most corners not yet held, with the inputs none of those
    corners needs set back to nominal. (Beyond :data:`_MAX_CANDIDATES` combinations the
    packing is first-fit: each point starts from the first corner not yet held and takes
    every later one that agrees with it on the inputs they share.)

    Returns
    -------
    list of dict : ``{dotted path: value}`` per point, the inputs at their nominal
    value left out.
    """
    sets = []
    for s in input_sets:
        s = tuple(dict.fromkeys(s))
        if 2 <= len(s) <= max_inputs and s not in sets:
            sets.append(s)
    names = list(dict.fromkeys(n for s in sets for n in s))
    levels = [ends(axes[n]) for n in names]
    col = {n: i for i, n in enumerate(names)}
    corners = [
        tuple((n, i) for n, i in zip(s, combo, strict=True))
        for s in sets
        for combo in np.ndindex(*(len(levels[col[n]]) for n in s))
    ]
    size = math.prod(len(lv) for lv in levels)
    chosen: list[dict[str, int]] = []
    if corners and size <= _MAX_CANDIDATES:
        cand = np.array(list(np.ndindex(*(len(lv) for lv in levels))))
        holds = np.ones((len(corners), size), dtype=bool)
        for i, corner in enumerate(corners):
            for n, lvl in corner:
                holds[i] &= cand[:, col[n]] == lvl
        left = np.ones(len(corners), dtype=bool)
        while left.any():
            j = int(np.argmax(holds[left].sum(axis=0)))
            new = np.flatnonzero(left & holds[:, j])
            needed = {n for i in new for n, _ in corners[i]}
            chosen.append({n: int(cand[j, col[n]]) for n in names if n in needed})
            left &= ~holds[:, j]
    else:
        remaining = list(corners)
        while remaining:
            point = dict(remaining[0])
            for corner in remaining[1:]:
                if all(point.get(n, lvl) == lvl for n, lvl in corner):
                    point.update(corner)
            chosen.append(point)
            remaining = [c for c in remaining if any(point.get(n) != lvl for n, lvl in c)]
    out = []
    for point in chosen:
        values = {n: levels[col[n]][lvl] for n, lvl in point.items()}
        out.append({n: v for n, v in values.items() if not _same(v, axes[n].nominal)})
    return out


def latin_hypercube(
    axes: Mapping[str, Axis], names: Sequence[str], n: int, seed: int
) -> list[dict[str, Any]]:
    """``n`` points of a Latin hypercube over ``names``, each coordinate on its grid.

    :class:`scipy.stats.qmc.LatinHypercube` (``d = len(names)``, ``scramble=True``,
    ``rng = numpy.random.default_rng(seed)``); coordinate ``u`` of an input with grid
    ``values`` (``m`` of them) picks ``values[min(floor(u m), m - 1)]``.

    Returns
    -------
    list of dict : ``{dotted path: value}`` per point, inputs at their nominal value
    left out.
    """
    from scipy.stats import qmc

    names = list(dict.fromkeys(names))
    if not names:
        return []
    u = qmc.LatinHypercube(d=len(names), rng=np.random.default_rng(int(seed))).random(int(n))
    out = []
    for row in u:
        point = {}
        for name, ui in zip(names, row, strict=True):
            vals = axes[name].values
            v = vals[min(int(math.floor(ui * len(vals))), len(vals) - 1)]
            if not _same(v, axes[name].nominal):
                point[name] = v
        out.append(point)
    return out


def joint_design(
    axes: Mapping[str, Axis], input_sets: Iterable[Sequence[str]], design: Design
) -> list[JointPoint]:
    """The joint design of one document: the packed corners (:func:`corner_design`) of
    the rows with ``2 .. design.corner_inputs`` inputs, then, when some row has more,
    ``design.joint_points`` points of a Latin hypercube (:func:`latin_hypercube`) over
    the union of those rows' inputs. Points that move at most one input (one-at-a-time
    points) and repeated points are dropped.
    """
    input_sets = [tuple(dict.fromkeys(s)) for s in input_sets]
    big = [n for s in input_sets if len(s) > design.corner_inputs for n in s]
    big = list(dict.fromkeys(big))
    out: list[JointPoint] = []
    seen = set()
    raw = [("corner", p) for p in corner_design(axes, input_sets, design.corner_inputs)]
    raw += [
        ("hypercube", p)
        for p in latin_hypercube(axes, big, design.joint_points, design.design_seed)
    ]
    count = {"corner": 0, "hypercube": 0}
    for kind, p in raw:
        count[kind] += 1
        key = tuple(sorted((n, _key(v)) for n, v in p.items()))
        if len(p) < 2 or key in seen:
            continue
        seen.add(key)
        out.append(JointPoint(kind, count[kind], dict(p)))
    return out


def point_seed_sets(
    axes: Mapping[str, Axis], joint: Sequence[JointPoint], n_sets: int
) -> tuple[dict[tuple[str, Any], int], list[int]]:
    """The seed set each point of the one-at-a-time and joint designs is drawn with.

    The points off the nominal inputs, in a fixed order (every input of ``axes`` in its
    declared order, each of its values but the nominal one in grid order, then the joint
    points in order), take the seed sets ``1 .. n_sets`` in turn: the i-th point set
    ``1 + i mod n_sets``. A Monte Carlo row is so judged under a fresh draw at every
    design point, not only at its nominal inputs: chance and inputs together. With no
    seed set (``n_sets = 0``: the document reads no seed) every point keeps the
    configured seeds (0).

    Returns
    -------
    (one_at_a_time, joint)
        ``{(input, value): k}`` (values as hashable keys: lists by their ``repr``) and the
        seed set of each joint point.
    """
    i = 0
    oat: dict[tuple[str, Any], int] = {}
    for name, ax in axes.items():
        for v in ax.values:
            if _same(v, ax.nominal):
                continue
            oat[name, _key(v)] = 1 + i % n_sets if n_sets else 0
            i += 1
    out = []
    for _ in joint:
        out.append(1 + i % n_sets if n_sets else 0)
        i += 1
    return oat, out


def draws_of_point(k: int, n_sets: int, per_point: int) -> list[int]:
    """The seed sets a Monte Carlo row is judged under at a joint point drawn with set
    ``k`` (:func:`point_seed_sets`): ``k`` and the next ``per_point - 1`` sets in turn,
    cycling through ``1 .. n_sets`` (so ``per_point`` distinct sets, since ``per_point
    <= n_sets``). With no seed set (``k = 0``) the configured seeds alone, ``[0]``.

    Raises
    ------
    AbglibValueError
        ``per_point`` outside ``[1, n_sets]`` or ``k`` outside ``[1, n_sets]`` when
        there are seed sets.
    """
    if n_sets == 0 or k == 0:
        return [0]
    if not 1 <= per_point <= n_sets:
        raise AbglibValueError(
            f"seed sets per joint point must satisfy 1 <= per_point <= {n_sets}, got {per_point}"
        )
    if not 1 <= k <= n_sets:
        raise AbglibValueError(f"seed set k must satisfy 1 <= k <= {n_sets}, got {k}")
    return [1 + (k - 1 + i) % n_sets for i in range(per_point)]


def project(point: JointPoint, inputs: Sequence[str]) -> tuple[tuple[str, Any], ...]:
    """The inputs of a row that ``point`` moves, with their values, in the row's order."""
    return tuple((n, point.values[n]) for n in inputs if n in point.values)


# --------------------------------------------------------------------------- chance
def confirmation_draws(k: int, n_sets: int, scheduled: int, confirm: int) -> list[int]:
    """The seed sets of the extra draws a Monte Carlo row gets at a design point drawn
    with set ``k`` whose ``scheduled`` draws (:func:`draws_of_point`) did not all give
    the row's nominal verdict: the sets after them in turn, up to ``confirm`` draws in
    all (none when ``scheduled >= confirm``)."""
    if confirm <= scheduled or n_sets == 0 or k == 0:
        return []
    return draws_of_point(k, n_sets, min(confirm, n_sets))[scheduled:]


def point_verdict(nominal: str, verdicts: Sequence[str], confirm: int) -> str:
    """The verdict of one design point from its draws.

    A point drawn once (a row that reads no seeded draw: its verdict is the same under
    every set) has that draw's verdict. A Monte Carlo row's point contradicts the
    nominal verdict only when at least ``confirm`` draws were made there and every one
    gives the same other verdict: the inputs, not chance, changed it. Otherwise it keeps
    the nominal verdict, and its contradicting draws count against the row's share under
    chance (:func:`chance_judgement`).

    With a per-draw contradiction rate ``p`` from chance alone, a point is so mistaken
    for a flip by the inputs with probability ``p**confirm`` (``confirm = 3``: 1.4e-5 at
    the largest rate a robust row may have, 2.4 %, seen at Al-Wagih's nominal inputs over
    41 draws), while a point whose inputs change the verdict outright is found always.
    """
    verdicts = list(verdicts)
    if not verdicts:
        raise AbglibValueError("a design point needs at least one draw, got none")
    if len(verdicts) == 1 and confirm <= 1:
        return verdicts[0]
    others = set(verdicts) - {nominal}
    if len(verdicts) >= confirm and len(others) == 1 and nominal not in verdicts:
        return others.pop()
    if len(verdicts) == 1:
        return verdicts[0] if confirm <= 1 else nominal
    return nominal


@functools.lru_cache(maxsize=4096)
def _beta_quantile(q: float, a: int, b: int) -> float:
    """``scipy.stats.beta.ppf(q, a, b)``, cached: a build asks for the same Clopper-Pearson
    bounds (a few confidence levels, small counts) thousands of times, ~0.1 ms each."""
    from scipy.stats import beta

    return float(beta.ppf(q, a, b))


@dataclass(frozen=True)
class ChanceJudgement:
    """A Monte Carlo row's verdict under chance (:func:`chance_judgement`).

    ``agree`` of ``draws`` draws give the nominal verdict; ``tolerance`` is the largest
    contradiction rate a robust verdict may have, ``confidence`` the one-sided level of
    the Clopper-Pearson bounds on that rate.
    """

    agree: int
    draws: int
    tolerance: float
    confidence: float

    @property
    def contradictions(self) -> int:
        return self.draws - self.agree

    @property
    def share(self) -> float:
        """Share of the draws that give the nominal verdict."""
        return self.agree / self.draws if self.draws else 1.0

    @property
    def upper(self) -> float:
        """One-sided Clopper-Pearson upper bound on the contradiction rate."""
        x, n = self.contradictions, self.draws
        if n == 0 or x >= n:
            return 1.0
        return _beta_quantile(self.confidence, x + 1, n - x)

    @property
    def lower(self) -> float:
        """One-sided Clopper-Pearson lower bound on the contradiction rate."""
        x, n = self.contradictions, self.draws
        if x == 0:
            return 0.0
        return _beta_quantile(1.0 - self.confidence, x, n - x + 1)

    @property
    def state(self) -> str:
        """``robust`` (the rate is below the tolerance at the confidence), ``fragile``
        (above it at the confidence) or ``undecided``.

        No draw contradicting is not enough by itself: 6 agreeing draws bound the rate
        only below 39 % at 95 %, and a row contradicted at 10 % agrees in 6 of 6 draws in
        53 % of rebuilds (v0.4.1 called such a row robust); with the defaults a row needs
        44 agreeing draws (``0.9**44 < 0.01``)."""
        if self.upper <= self.tolerance:
            return "robust"
        if self.lower > self.tolerance:
            return "fragile"
        return "undecided"

    @property
    def robust(self) -> bool:
        return self.state == "robust"

    def describe(self) -> str:
        """``'holds in 63 of 64 draws (98 %; contradicted at a rate < 9.93 % at 99 %
        confidence: robust to chance, which needs < 10 %)'``."""
        pct = f"{100 * self.share:.0f} %"
        conf = f"{100 * self.confidence:.0f} %"
        need = f"{100 * self.tolerance:.0f} %"
        if self.state == "robust":
            what = f"rate < {100 * self.upper:.2f} % at {conf} confidence: robust to chance"
        elif self.state == "fragile":
            what = f"rate > {100 * self.lower:.2f} % at {conf} confidence: not robust to chance"
        else:
            what = (
                f"rate between {100 * self.lower:.2f} and {100 * self.upper:.2f} % at {conf} "
                f"confidence, undecided at the most draws: not robust to chance"
            )
        return (
            f"holds in {self.agree} of {self.draws} draws ({pct}; contradicted at a {what}, "
            f"which needs < {need})"
        )


def chance_judgement(
    nominal: str,
    verdicts: Sequence[str],
    tolerance: float,
    confidence: float = DEFAULTS["chance_confidence"],
) -> ChanceJudgement:
    """Whether a Monte Carlo row's nominal verdict survives chance.

    ``verdicts`` are the row's *scheduled* draws: the configured seeds and every seed set
    at its nominal inputs, and the first :func:`draws_of_point` draws at each design point
    that is not a flip by the inputs (:func:`point_verdict`; confirmation draws are left
    out, since they are drawn only after a contradiction and would bias the rate). The
    verdict is robust to chance when its contradiction rate is below ``tolerance``
    (``robustness.chance_tolerance``, 0.1: the referee's "nine realisations in ten
    reproduce it") at one-sided ``confidence`` (``robustness.chance_confidence``, 0.99
    a look; Clopper-Pearson), fragile when above it; the
    caller draws more while it is undecided, over the same mixture of points
    (:func:`extra_draws`; ``robustness.chance_draws`` in all at most) and calls an
    undecided row fragile.

    Why a rate, not "every draw agrees": a verdict that rests on one realisation of a
    random experiment (the Section 7 t-tests of Al-Wagih, one run per experiment) is a
    Bernoulli outcome. Under "every draw agrees" a row contradicted at a few per cent of
    draws is robust in some rebuilds and fragile in others (with about 45 draws, a
    rebuild with every seed shifted flipped 1 to 7 such rows, and no number of draws up to
    4 per joint point fixed it): the label measured the luck of the draw. A point
    estimate against the tolerance (tried first) still flipped a row whose rate is near
    it (Huang, Figs 6-7 conclusion: 40 of 42 draws agree under the configured seeds, 35
    of 42 with every seed shifted by 7919). With the bound, such a row is drawn until its
    rate is known to lie on one side; a row robust in one build can be fragile in another
    only when its rate lies in the band below the tolerance that
    :func:`robust_probability` computes.
    """
    verdicts = list(verdicts)
    agree = sum(v == nominal for v in verdicts)
    return ChanceJudgement(agree, len(verdicts), float(tolerance), float(confidence))


@functools.lru_cache(maxsize=4096)
def _looks(n: int, tolerance: float, confidence: float) -> tuple[int, int]:
    """At ``n`` draws, the most contradictions that are robust (-1: none is) and the
    fewest that are fragile (``n + 1``: none is), by :class:`ChanceJudgement` itself."""

    def state(x: int) -> str:
        return ChanceJudgement(n - x, n, tolerance, confidence).state

    # both bounds grow with x: robust for x <= r, fragile for x >= f (bisection)
    lo, hi = -1, n  # state(lo) robust or lo = -1; state(hi + 1) not robust or hi = n
    while lo < hi:
        mid = (lo + hi + 1) // 2
        lo, hi = (mid, hi) if state(mid) == "robust" else (lo, mid - 1)
    r = lo
    lo, hi = r + 1, n + 1  # the fewest fragile in (r, n], n + 1 when none is
    while lo < hi:
        mid = (lo + hi) // 2
        lo, hi = (lo, mid) if state(mid) == "fragile" else (mid + 1, hi)
    f = lo
    return r, f


def robust_probability(
    rate: float, scheduled: int, design: Design | None = None
) -> tuple[float, float]:
    """How often the rule under chance calls a row robust, exactly.

    A Monte Carlo row contradicted at ``rate`` per draw, with ``scheduled`` draws before
    the first look (:func:`chance_judgement`), is looked at after every further draw
    until it is robust or fragile or has ``design.chance_draws`` draws (then it is
    fragile). Looking after every draw spends the per-look ``chance_confidence`` many
    times over, so this computes what the whole sequence does: the probability that the
    row ends robust, by dynamic programming over (draws, contradictions), and the
    expected number of draws it takes. Checked against a simulation of the sequence
    in ``tests/test_robustness.py``.

    With the defaults (10 %, 99 % per look, at most 500 draws) a row at the tolerance is
    robust in at most about 6 % of rebuilds whatever its scheduled draws (at 95 % per
    look and 150 draws, the v0.4.1 rule, 13 % with 46 scheduled draws, and 59 % with 6
    since no contradiction counted as robust); a row at 5 % in at least 98 %; between
    them lies the band where the label is a toss of the draws (50 % near 7.5 %).

    Parameters
    ----------
    rate : float
        Per-draw contradiction rate, in [0, 1].
    scheduled : int
        Draws before the first look (at least 1, at most ``design.chance_draws``).
    design : Design, optional
        The tolerance, confidence and cap (default :data:`DEFAULTS`).

    Returns
    -------
    (probability robust, expected draws)
    """
    from scipy.stats import binom

    d = design or Design()
    cap = d.chance_draws
    if not 0.0 <= rate <= 1.0:
        raise AbglibValueError(f"rate must satisfy 0 <= rate <= 1, got {rate}")
    if not 1 <= scheduled <= cap:
        raise AbglibValueError(f"scheduled must satisfy 1 <= scheduled <= {cap}, got {scheduled}")
    dist = binom.pmf(np.arange(scheduled + 1), scheduled, rate)
    robust = drawn = 0.0
    for n in range(scheduled, cap + 1):
        # at most r contradictions: robust; at least f: fragile (_looks)
        r, f = _looks(n, d.chance_tolerance, d.chance_confidence)
        robust += dist[: r + 1].sum()
        drawn += n * (dist[: r + 1].sum() + dist[f:].sum())
        dist[: r + 1] = 0.0
        dist[f:] = 0.0
        if n == cap:
            drawn += n * dist.sum()  # undecided at the most draws: fragile
            break
        dist = np.append(dist * (1.0 - rate), 0.0) + np.append(0.0, dist * rate)
    return float(robust), float(drawn)


def extra_draws(
    point_ids: Sequence[int], n_points: int, n_sets: int, count: int, start: int = 0
) -> list[tuple[int, int]]:
    """Where and with which seed set a Monte Carlo row undecided under chance is drawn
    again (:func:`chance_judgement`).

    The row's scheduled draws estimate its contradiction rate over a mixture: its nominal
    inputs and every design point that is not a flip by the inputs (``point_ids``: each
    point's number among the document's ``n_points`` points, 0 the nominal inputs). The
    extra draws continue that same mixture, so that however many are needed the rate
    they bound is one quantity: the ``j``-th extra draw (``j = start, start + 1, ...``)
    is the ``r = j // len(point_ids)``-th extra visit of point ``i = j mod
    len(point_ids)``, drawn with seed set ``n_sets + 1 + r * n_points + point_ids[i]``:
    a set no design point was drawn with (:func:`seed_set`), a different one for every
    visit of every point (so the draws are independent), and the same for every row
    that visits that point that often (so the rows share the study).

    Why not elsewhere (measured with every seed shifted by 104729, 7919 and 1299709):
    extra draws at the nominal inputs alone (v0.4.1) bounded a mixture that moved
    towards the nominal inputs' rate as draws were added. An Al-Wagih row (Table 4, M1
    vs M3, Y), contradicted at 1 % of the draws there but at about a quarter of them at
    the joint points with ``m1_alpha = 0.01``, was so robust by a hair (134 of 142
    draws, bound 9.94 %) under the configured seeds and fragile under the shift
    1299709. Extra draws only where contradictions were (tried) are chosen by the draws
    themselves and flipped more rows (3, 1, 1 against 1, 0, 0).

    Returns
    -------
    list of (index into ``point_ids``, seed set)
    """
    m = len(point_ids)
    if m < 1:
        raise AbglibValueError("extra draws need at least one point, got none")
    bad = [p for p in point_ids if not 0 <= p < n_points]
    if bad:
        raise AbglibValueError(f"point ids must satisfy 0 <= id < {n_points}, got {bad}")
    if count < 0 or start < 0:
        raise AbglibValueError(f"extra draws need count >= 0 and start >= 0, got {count}, {start}")
    return [
        (j % m, n_sets + 1 + (j // m) * n_points + point_ids[j % m])
        for j in range(start, start + count)
    ]


def seed_set(config: Mapping, doc: str, k: int, design: Design) -> dict:
    """The config of seed set ``k`` (every seed moved by ``k * design.seed_prime``), for
    any ``k >= 1``: the sets beyond ``design.seed_sets`` are the extra draws of a row
    whose verdict under chance is undecided (:func:`chance_judgement`)."""
    if k < 1:
        raise AbglibValueError(f"seed set k must satisfy k >= 1, got {k}")
    return with_seeds_shifted(config, doc, k * design.seed_prime)


# --------------------------------------------------------------------------- notes
def _fmt(v) -> str:
    return format_number(v, 4) if _is_number(v) else str(v)


def _short(name: str) -> str:
    # 'alwagih.reconstruction.noise_scale' -> 'reconstruction.noise_scale'
    return name.split(".", 1)[1] if "." in name else name


def describe_point(projection: Sequence[tuple[str, Any]]) -> str:
    """``'reconstruction.noise_scale=2, m1_alpha=0.2'`` (the document prefix dropped)."""
    return ", ".join(f"{_short(n)}={_fmt(v)}" for n, v in projection)


def describe_joint(judged: Sequence[tuple], limit: int = 6, drawn: str = "") -> str:
    """Where each verdict holds over the joint points of one row.

    ``judged`` lists ``(projection, verdict)``, or ``(projection, verdict, k)`` when a
    point is judged under several seed sets (a Monte Carlo row, :func:`draws_of_point`):
    one entry per draw, ``k`` its seed set. The verdicts held at fewer draws are listed
    draw by draw (at most ``limit`` each, then a count; with the seed set when a point
    has several draws); the most common one by its count. ``drawn`` is added to the
    design's description (e.g. how the points were drawn).
    """
    # a projection's values may be lists (a diagonal): count points by their keys
    points = list(dict.fromkeys(tuple((n, _key(v)) for n, v in e[0]) for e in judged))
    per_point = len(judged) // len(points) if points else 1
    by: dict[str, list] = {}
    for e in judged:
        by.setdefault(e[1], []).append(e)
    order = sorted(by, key=lambda v: (-len(by[v]), v))

    def where(e) -> str:
        if per_point > 1 and len(e) > 2:
            return f"{describe_point(e[0])} (seed set {e[2]})"
        return describe_point(e[0])

    parts = []
    for i, v in enumerate(order):
        pts = by[v]
        if i == 0 and len(order) > 1:
            parts.append(f"{v} at {len(pts)} of them")
            continue
        listed = "; ".join(where(e) for e in pts[:limit])
        more = f"; and {len(pts) - limit} more (robustness.csv)" if len(pts) > limit else ""
        parts.append(f"{v} at {len(pts)}: {listed}{more}")
    what = f"{len(points)} points moving 2 or more inputs at once"
    if per_point > 1:
        what += f", {len(judged)} draws: each point under {per_point} seed sets"
    return f"jointly ({what}{drawn}): " + ", ".join(parts)


def describe_seed_sets(
    verdicts: Sequence[str], design: Design, sets: Sequence[int] | None = None
) -> str:
    """Where each verdict holds over the seed sets of one row: ``verdicts[i]`` is the
    verdict under set ``sets[i]`` (default ``i``; set 0 the configured seeds). The extra
    draws under chance at the nominal inputs are drawn with sets further apart
    (:func:`extra_draws`), so their numbers are given."""
    if sets is None:
        sets = range(len(verdicts))
    if len(sets) != len(verdicts):
        raise AbglibValueError(f"one seed set per verdict: {len(sets)} sets, {len(verdicts)}")
    by: dict[str, list[int]] = {}
    for k, v in zip(sets, verdicts, strict=True):
        by.setdefault(v, []).append(k)
    parts = [
        f"{v} under set{'s' if len(ks) > 1 else ''} {', '.join(map(str, ks))}"
        for v, ks in sorted(by.items(), key=lambda kv: kv[1][0])
    ]
    return (
        f"under {len(verdicts) - 1} seed sets besides the configured one (set 0; set k "
        f"moves every seed by k x {design.seed_prime}): " + ", ".join(parts)
    )
