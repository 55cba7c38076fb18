"""Generated, compiled kernels: emission toolkit (:mod:`~assur.kernel.emit`), source
generator (:mod:`~assur.kernel.source`), disk cache (:mod:`~assur.kernel.cache`) and
threaded execution (:mod:`~assur.kernel.run`)."""

from .cache import cache_dir, set_cache_dir
from .run import set_threads, threads

__all__ = ["cache_dir", "set_cache_dir", "set_threads", "threads"]
