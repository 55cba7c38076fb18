"""A bounded load test of the page's server on loopback (issue 13): 50 requests/s for
5 s, open loop (each request is sent at its scheduled time, whether the earlier ones
have been answered or not), every request answered and no error allowed — a request
that meets a keep-alive connection the server has just closed is sent again once on a
new connection, as browsers do, and counted. The figures — requests per second kept,
the latencies' p50, p99 and maximum, the wall time — are printed (measured, never
asserted: a load test asserts errors and completeness, not the speed of the machine
it runs on).

The server is ``assur serve`` in its own process, on 127.0.0.1 and a free port. The
requests are what a page sends while a slider moves: ``POST /api/analyze`` of
the seed-003 hitch at 101 positions with the implement's weight P6 taking one of
five values (each answer is computed: the server keeps no results), and every
tenth request ``GET /api/model``.
"""

import contextlib
import http.client
import json
import re
import subprocess
import sys
import threading
import time
import urllib.request
from concurrent.futures import ThreadPoolExecutor
from urllib.parse import urlparse

import numpy as np
import pytest

from assur.io import bundled

pytestmark = pytest.mark.slow

RATE = 50        # requests per second
DURATION = 5     # seconds of the schedule

#: how a request fails on a keep-alive connection the server has just closed
STALE = (BrokenPipeError, ConnectionResetError, http.client.RemoteDisconnected)


@contextlib.contextmanager
def served(path):
    """``assur serve path --port 0 --no-browser`` in its own process (the load
    generator does not share its interpreter); yields the page's URL."""
    proc = subprocess.Popen([sys.executable, "-u", "-m", "assur", "serve", str(path),
                             "--port", "0", "--no-browser"], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    try:
        line = proc.stdout.readline()
        m = re.search(r"at (http://127\.0\.0\.1:\d+)/", line)
        assert m, f"assur serve printed {line!r}"
        url = m.group(1)
        for _ in range(300):  # until it answers
            try:
                with urllib.request.urlopen(url + "/api/model", timeout=5):
                    break
            except OSError:
                time.sleep(0.1)
        yield url
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
        proc.stdout.close()


def test_fifty_requests_per_second_all_answered_without_error(page_log):
    local = threading.local()
    conns, stale, lock = [], [], threading.Lock()

    with served(bundled("hitch_003")) as url:
        host, port = urlparse(url).hostname, urlparse(url).port

        def connection():
            conn = getattr(local, "conn", None)
            if conn is None:
                conn = local.conn = http.client.HTTPConnection(host, port, timeout=60)
                with lock:
                    conns.append(conn)
            return conn

        def send(conn, i):
            if i % 10 == 9:
                conn.request("GET", "/api/model")
            else:
                body = json.dumps({"params": {"P6": 25.0 + (i % 5)}, "positions": 101})
                conn.request("POST", "/api/analyze", body=body,
                             headers={"Content-Type": "application/json"})
            r = conn.getresponse()
            return r, r.read()

        def call(i):
            t0 = time.perf_counter()
            reused = getattr(local, "conn", None) is not None
            try:
                try:
                    r, data = send(connection(), i)
                except STALE:
                    # the server closed this thread's idle keep-alive connection (uvicorn
                    # after 5 s) as the request went out: a client retries an idempotent
                    # request once on a new connection, as browsers and urllib3 do — a
                    # failure on a new connection is an error
                    if not reused:
                        raise
                    local.conn = None
                    with lock:
                        stale.append(i)
                    r, data = send(connection(), i)
            except (OSError, http.client.HTTPException) as e:
                local.conn = None
                return time.perf_counter() - t0, f"{type(e).__name__}: {e}"
            dt = time.perf_counter() - t0
            if r.status != 200:
                return dt, f"HTTP {r.status}: {data[:200]!r}"
            if i % 10 != 9 and not json.loads(data)["ok"]:
                return dt, f"not ok: {data[:200]!r}"
            return dt, None

        call(0)  # warm: kernels and the solve cache
        n = RATE * DURATION
        futures = []
        with ThreadPoolExecutor(max_workers=32) as pool:
            start = time.perf_counter()
            for i in range(n):
                delay = start + i / RATE - time.perf_counter()
                if delay > 0:
                    time.sleep(delay)
                futures.append(pool.submit(call, i))
            results = [f.result() for f in futures]
            elapsed = time.perf_counter() - start
        for c in conns:
            c.close()
    lat = np.array([r[0] for r in results]) * 1e3
    errors = [r[1] for r in results if r[1]]
    page_log(f"\nload test: {n} requests in {elapsed:.1f} s ({n / elapsed:.1f}/s), "
             f"{len(errors)} errors, {len(stale)} retried on a new connection after the "
             f"server closed an idle one; latency p50 {np.percentile(lat, 50):.1f} ms, "
             f"p99 {np.percentile(lat, 99):.1f} ms, max {lat.max():.1f} ms")
    # every scheduled request was sent and has its result (f.result() above): an
    # answer with status 200 and, for an analysis, "ok" — or the error it met
    assert not errors, errors[:5]

