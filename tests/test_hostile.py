"""Hostile input through the API, property-based: whatever the program text, a run ends (returns or
raises ``NgcError``), within a time limit, and writes no file.

Three strategies, built on the generators of tests/fuzz/hostile.py (which tests/fuzz/soak.py runs
by the million): random bytes, token soup (G-code tokens, numbers huge, tiny and non-finite,
operators, functions, o-words, comments of every kind, known-hard constructs) and mutated golden
programs.  Bounded and reproducible for CI: a fixed number of examples per strategy, derandomized,
no example database.  The generators draw from a seeded ``random.Random`` (hypothesis picks the
seed): drawing every choice through hypothesis would let it shrink them, but costs twenty times
the time; shrinking is off anyway (a program that hangs would cost the time limit per shrink
step).  A failure prints the program as found: minimize it with
``python tests/fuzz/soak.py --shrink FILE``.
"""

from __future__ import annotations

import os
import sys
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, note, settings
from hypothesis import strategies as st

from ngc.errors import NgcError

sys.path.insert(0, str(Path(__file__).parent / "fuzz"))

import hostile

TIME_LIMIT_S = 2.0
CORPUS = hostile.golden_corpus()

BOUNDED = settings(
    deadline=None,
    derandomize=True,
    database=None,
    phases=(Phase.explicit, Phase.generate),
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                           HealthCheck.large_base_example],
)


def _from(generator: Callable[[object], bytes]) -> st.SearchStrategy[bytes]:
    """A hostile.py generator as a strategy, on a Random seeded by hypothesis."""
    return st.randoms(use_true_random=True).map(generator)  # type: ignore[arg-type]


random_bytes = st.one_of(st.binary(max_size=400), _from(hostile.random_bytes))
token_soup = _from(hostile.token_soup)


@st.composite
def mutated_golden(draw: st.DrawFn) -> bytes:
    program = draw(st.sampled_from(CORPUS))
    return hostile.mutate(draw(st.randoms(use_true_random=True)), program)


decodings = st.sampled_from(hostile.DECODINGS)
feeds = st.sampled_from(hostile.FEEDS)


@pytest.fixture(scope="module")
def workdir() -> Iterator[Path]:
    """An empty working directory for the runs (a program must leave it empty)."""
    old = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="ngc-hostile-") as tmp:
        os.chdir(tmp)
        try:
            yield Path(tmp)
        finally:
            os.chdir(old)


def ends_cleanly(data: bytes, decoding: str, feed: str, workdir: Path) -> None:
    """The property: the run returns or raises NgcError, in time, leaving no file behind."""
    note(f"program: {data!r} (read as {decoding}, fed as {feed})")
    text = hostile.decode(data, decoding)
    try:
        with hostile.time_limit(TIME_LIMIT_S):
            hostile.run_api(text, feed=feed)
    except NgcError:
        pass
    except hostile.Overtime:
        pytest.fail(f"still running after {TIME_LIMIT_S:g} s")
    left = sorted(os.listdir(workdir))
    for name in left:
        (workdir / name).unlink()
    assert not left, f"the program wrote {left}"


@settings(BOUNDED, max_examples=500)
@given(data=random_bytes, decoding=decodings, feed=feeds)
def test_random_bytes(data: bytes, decoding: str, feed: str, workdir: Path) -> None:
    ends_cleanly(data, decoding, feed, workdir)


@settings(BOUNDED, max_examples=1500)
@given(data=token_soup, decoding=decodings, feed=feeds)
def test_token_soup(data: bytes, decoding: str, feed: str, workdir: Path) -> None:
    ends_cleanly(data, decoding, feed, workdir)


@settings(BOUNDED, max_examples=1000)
@given(data=mutated_golden(), decoding=decodings, feed=feeds)
def test_mutated_golden(data: bytes, decoding: str, feed: str, workdir: Path) -> None:
    ends_cleanly(data, decoding, feed, workdir)
