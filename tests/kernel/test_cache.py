"""The disk cache of generated kernels (:mod:`assur.kernel.cache`): a source is written
once under the hash of its text and imported once per process; a file that does not
hold its source is written again; a keyed module is made only on its key's first
use; the directory follows ``ASSUR_CACHE_DIR`` or :func:`set_cache_dir`; the helpers'
tag is the hash of the intrinsics' modules."""

import hashlib
from pathlib import Path

import pytest

from assur.kernel import cache as C


@pytest.fixture
def tmp_cache(tmp_path):
    C.set_cache_dir(tmp_path)
    try:
        yield tmp_path / "kernels"
    finally:
        C.set_cache_dir(None)


def test_a_source_is_written_once_by_its_hash_and_loaded_once(tmp_cache):
    src = "def kernel(x):\n    return 3 * x  # test_cache\n"
    f = C.load_source(src)
    path = tmp_cache / f"k_{hashlib.sha1(src.encode()).hexdigest()[:20]}.py"
    assert f(2) == 6 and path.read_text() == src
    stamp = path.stat().st_mtime_ns
    assert C.load_source(src) is f and path.stat().st_mtime_ns == stamp
    other = C.load_source(src.replace("3 * x", "4 * x"))
    assert other(2) == 8 and len(list(tmp_cache.glob("k_*.py"))) == 2


def test_a_damaged_file_is_written_again(tmp_cache):
    src = "def kernel(x):\n    return x - 1  # test_cache damaged\n"
    path = tmp_cache / f"k_{hashlib.sha1(src.encode()).hexdigest()[:20]}.py"
    tmp_cache.mkdir(parents=True, exist_ok=True)
    path.write_text("def kernel(x):\n    return 'half a file'")
    assert C.load_source(src)(5) == 4 and path.read_text() == src


def test_a_keyed_module_is_made_on_its_first_use_only(tmp_cache):
    made = []

    def make():
        made.append(1)
        return "def kernel(x):\n    return x + 10\n"

    f = C.load_keyed("test_cache: add ten", make)
    assert f(1) == 11 and C.load_keyed("test_cache: add ten", make) is f and made == [1]


def test_the_directory_and_the_helpers_tag(monkeypatch, tmp_path):
    monkeypatch.setenv("ASSUR_CACHE_DIR", str(tmp_path / "env"))
    assert C.cache_dir() == tmp_path / "env" / "kernels" and C.cache_dir().is_dir()
    C.set_cache_dir(tmp_path / "set")
    try:
        assert C.cache_dir() == tmp_path / "set" / "kernels"
    finally:
        C.set_cache_dir(None)
    from assur.kernel import select, stream
    h = hashlib.sha1(Path(select.__file__).read_bytes() + Path(stream.__file__).read_bytes())
    assert C.helpers_tag() == h.hexdigest()[:12]
