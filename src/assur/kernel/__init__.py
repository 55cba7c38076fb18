"""Generated, compiled kernels: emission toolkit (:mod:`~assur.kernel.emit`), source
generator of the fused kernel (:mod:`~assur.kernel.source`), composed kernels of
shared per-group functions for large structures (:mod:`~assur.kernel.compose`),
branch-free selects (:mod:`~assur.kernel.select`), disk cache
(:mod:`~assur.kernel.cache`) and threaded execution (:mod:`~assur.kernel.run`)."""

from .cache import cache_dir, set_cache_dir
from .run import set_threads, threads

__all__ = ["cache_dir", "set_cache_dir", "set_threads", "threads"]
