"""A per-client token bucket, in memory: one browser that submits in a loop
gets 429 and cannot stall the class. Behind a reverse proxy the client is the
address the proxy forwards (serve --behind-proxy)."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

__all__ = ["TokenBuckets"]


class TokenBuckets:
    """`burst` tokens per client, refilled at `rate` per second; a request
    takes `cost` of them or is refused."""

    def __init__(
        self,
        burst: float,
        rate: float,
        *,
        clients_max: int = 10_000,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.burst = float(burst)
        self.rate = float(rate)
        self.clients_max = clients_max
        self._clock = clock
        self._lock = threading.Lock()
        self._buckets: dict[str, tuple[float, float]] = {}  # client: (tokens, time)

    def take(self, client: str, cost: float = 1.0) -> float:
        """0 when the request may go on; else the seconds to wait."""
        now = self._clock()
        with self._lock:
            tokens, then = self._buckets.get(client, (self.burst, now))
            tokens = min(self.burst, tokens + (now - then) * self.rate)
            if tokens < cost:
                self._buckets[client] = (tokens, now)
                return (cost - tokens) / self.rate if self.rate > 0 else 60.0
            self._buckets[client] = (tokens - cost, now)
            if len(self._buckets) > self.clients_max:
                self._prune(now)
            return 0.0

    def _prune(self, now: float) -> None:
        """Forget the clients whose buckets are full again (they lose nothing)."""
        full = [
            c
            for c, (t, then) in self._buckets.items()
            if t + (now - then) * self.rate >= self.burst
        ]
        for c in full:
            del self._buckets[c]
        while len(self._buckets) > self.clients_max:  # all busy: the oldest go
            del self._buckets[next(iter(self._buckets))]
